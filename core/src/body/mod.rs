//! body (work in progress).
