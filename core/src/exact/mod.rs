//! exact (work in progress).
