//! Tests of the whole derive (added below).
