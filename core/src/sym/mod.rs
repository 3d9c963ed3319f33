//! sym (work in progress).
