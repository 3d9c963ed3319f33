//! Where an interpreted program writes while it runs: the environment with the per-call
//! inputs, the values of its instructions, and its outputs when their number is known only
//! at run time.
//!
//! The models keep none of this themselves, so they are `Send + Sync`. Callers who step
//! many trajectories on one thread may own an [`EvalWorkspace`] and pass it
//! ([`super::Bindings::eval_in`]); everything else — above all `System::rhs`, which takes
//! `&self` and has no place for one — uses the calling thread's own workspace.
//!
//! Why a thread's own rather than one per call or one behind a lock: a fresh workspace per
//! call would allocate on every right-hand side (the steppers' inner loop must not), and a
//! lock would serialise the threads of an ensemble that share one model. A thread-local
//! workspace is allocated once per thread, grows to the largest program the thread runs,
//! and no two threads ever touch the same one. Changing `System::rhs` to take a workspace
//! would reach into every stepper and every user's system for no gain over this.

use std::cell::RefCell;
use std::sync::atomic::{AtomicU64, Ordering};

/// The buffers one evaluation writes into, reusable across calls and models.
///
/// Holding one per thread and passing it to [`super::Bindings::eval_in`] is the explicit
/// form of what [`super::Bindings::eval`] does with the thread's own.
///
/// ```
/// use precess_core::codegen::{Bindings, EvalWorkspace, Program};
/// use precess_core::sym::Arena;
///
/// let mut a = Arena::new();
/// let (x, k) = (a.input("x"), a.parameter("k"));
/// let e = a.mul(k, x);
/// let p = Program::lower(&a, &[e]);
/// let x_id = a.as_symbol(x).ok_or("x is a symbol")?;
/// let b = Bindings::new(&a, std::slice::from_ref(&p), &[x_id], &[("k", 3.0)])?;
/// let mut ws = EvalWorkspace::new();
/// let mut out = [0.0];
/// b.eval_in(&mut ws, &p, [(x_id, 2.0)], &mut out);
/// assert_eq!(out[0], 6.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Default)]
pub struct EvalWorkspace {
    /// Which parameter values `env` holds (0: none yet).
    pub(super) generation: u64,
    /// Every symbol's value: the parameters copied from the bindings, the inputs of the
    /// current call written over them.
    pub(super) env: Vec<f64>,
    /// The value of each instruction.
    pub(super) scratch: Vec<f64>,
    /// The outputs of [`super::Bindings::eval_to`].
    pub(super) out: Vec<f64>,
}

impl EvalWorkspace {
    /// An empty workspace; it grows on first use.
    pub const fn new() -> EvalWorkspace {
        EvalWorkspace {
            generation: 0,
            env: Vec::new(),
            scratch: Vec::new(),
            out: Vec::new(),
        }
    }
}

/// The source of [`super::Bindings`] generations; 0 is never handed out, so an empty
/// workspace matches no bindings.
static GENERATION: AtomicU64 = AtomicU64::new(1);

/// A generation no bindings has had before.
pub(super) fn next_generation() -> u64 {
    GENERATION.fetch_add(1, Ordering::Relaxed)
}

thread_local! {
    static WORKSPACE: RefCell<EvalWorkspace> = const { RefCell::new(EvalWorkspace::new()) };
}

/// Runs `f` with the calling thread's workspace.
///
/// Never panics: when the thread's workspace is unavailable (already in use further up the
/// stack, or the thread is being torn down) `f` gets a fresh one, which costs an allocation
/// and nothing else.
pub(crate) fn with_workspace(f: impl FnOnce(&mut EvalWorkspace)) {
    let mut f = Some(f);
    // The closure runs at most once and takes `f` when it does; if the thread's storage is
    // gone it never runs and `f` is still here for the fallback below.
    let _ = WORKSPACE.try_with(|cell| {
        if let Some(f) = f.take() {
            match cell.try_borrow_mut() {
                Ok(mut ws) => f(&mut ws),
                Err(_) => f(&mut EvalWorkspace::new()),
            }
        }
    });
    if let Some(f) = f {
        f(&mut EvalWorkspace::new());
    }
}
