//! ode (work in progress).
