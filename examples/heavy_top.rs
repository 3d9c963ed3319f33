//! A spinning top derived by the macro, simulated, and measured against theory.
//!
//! The top is `precess::models::HeavyTop`, a brass disk on a steel stem, its tip on a fixed
//! pivot, declared as a user would: `#[derive(RigidBody)]`
//! computes its inertia about the pivot at compile time and `#[top(gravity = 9.81)]` emits its
//! Euler-angle equations of motion. Released at rest 20° from the vertical while spinning at
//! 150 rad/s, it nutates and precesses; the exact nutation of the symmetric heavy top (the
//! cubic in u = cos θ, Jacobi's sn) gives the amplitude, the period and the mean precession
//! rate to compare with. Three integrators run the same top: DOP853 on the generated angle
//! equations, DOP853 on the generated Eulerian form, and a splitting with the exact
//! free-body flow and gravity kicks, whose step the fast spin does not limit.
//!
//! Run with `cargo run --release --example heavy_top`; it writes θ(t) and the phase portrait
//! (θ, θ̇) to `target/precess-plots/` with `precess::plot`.
//!
//! Each run is measured by the library's events and observers rather than by hand: the
//! turning points are the zero crossings of θ̇ (located on each method's own solution), the
//! precession angle is followed through ±π by an observer of every step, and a progress bar
//! appears for any run that takes longer than a second (the long run at the end does, and
//! so do the short ones in a debug build).

mod common;

use std::time::{Duration, Instant};

use common::{Table, plot_dir};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use precess::nalgebra::Quaternion;
use precess::ode::{AdaptiveConfig, Control, Direction, Dop853, Event, FixedStepConfig};
use precess::ode::{FixedStepper, Progress, Run, Stepper};
use precess::prelude::*;
use precess::rigid::{BodyMomentum, ExactFreeFlow, Gravity, PotentialSplitting};
use precess::top::{HeavyTopTheory, TopQuantities};
use precess::{animate, plot};

// The library's ready heavy top: a disk (brass, 40 mm radius) 50 mm up a stem (steel,
// 80 mm), turning on the stem's tip.
use precess::models::HeavyTop as SpinningTop;

/// The precession angle φ of the symmetry axis (ZXZ: axis = (sin φ sin θ, −cos φ sin θ,
/// cos θ)), followed continuously through ±π.
#[derive(Default)]
struct Unwrap {
    total: f64,
    last: f64,
}

impl Unwrap {
    fn add(&mut self, phi: f64) -> f64 {
        let d = phi - self.last;
        self.total += d - (d / std::f64::consts::TAU).round() * std::f64::consts::TAU;
        self.last = phi;
        self.total
    }
}

/// φ of the symmetry axis.
fn precession_angle(axis: &Vector3<f64>) -> f64 {
    axis.x.atan2(-axis.y)
}

/// A progress bar that stays hidden until the run has taken a second; the caller clears it.
fn progress_bar(
    label: &str,
) -> Result<(ProgressBar, impl FnMut(&Progress)), Box<dyn std::error::Error>> {
    let bar = ProgressBar::with_draw_target(Some(1000), ProgressDrawTarget::hidden());
    bar.set_style(ProgressStyle::with_template(
        "{msg:34} [{bar:40}] {percent:>3}% {elapsed}",
    )?);
    bar.set_message(label.to_string());
    let (shown, started) = (bar.clone(), Instant::now());
    let report = move |p: &Progress| {
        if shown.is_hidden() && started.elapsed() > Duration::from_secs(1) {
            shown.set_draw_target(ProgressDrawTarget::stderr());
        }
        shown.set_position((p.fraction() * 1000.0) as u64);
    };
    Ok((bar, report))
}

/// What a simulation measured.
struct Measured {
    theta_max: f64,
    period: f64,
    mean_precession: f64,
    energy_drift: f64,
    steps: u64,
    seconds: f64,
}

/// How to read a stepper's state: θ̇ up to a positive factor (its zeros are the turning
/// points), θ, the symmetry axis's precession angle φ, and the energy.
struct Reading<'r, St> {
    theta_rate: Box<dyn Fn(&St) -> f64 + 'r>,
    theta: Box<dyn Fn(&St) -> f64 + 'r>,
    phi: Box<dyn Fn(&St) -> f64 + 'r>,
    energy: Box<dyn Fn(&St) -> f64 + 'r>,
}

/// Runs `stepper` to `t_end` with an event at θ̇ = 0 and an observer unwrapping φ.
fn measure<S: Stepper>(
    label: &str,
    stepper: &mut S,
    t_end: f64,
    read: &Reading<S::State>,
) -> Result<Measured, Box<dyn std::error::Error>> {
    let started = Instant::now();
    let e0 = (read.energy)(stepper.state());
    let mut unwrap = Unwrap::default();
    unwrap.add((read.phi)(stepper.state()));
    let (bar, report) = progress_bar(label)?;
    let out = Run::new(stepper, t_end)
        .sample_none()
        .event(Event::new("turning point"), |_t, y| (read.theta_rate)(y))
        .observe(|_t, y| {
            unwrap.add((read.phi)(y));
            Control::Continue
        })
        .progress(report)
        .integrate()?;
    bar.finish_and_clear();
    // θ̇ falls through 0 at θ_max and rises through 0 back at θ_min = θ0, once a period.
    let lows: Vec<f64> = out
        .events
        .iter()
        .filter(|h| h.direction == Direction::Rising)
        .map(|h| h.t)
        .collect();
    let period = match lows.as_slice() {
        [first, .., last] => (last - first) / (lows.len() - 1) as f64,
        _ => f64::NAN,
    };
    let theta_max = out
        .events
        .iter()
        .filter(|h| h.direction == Direction::Falling)
        .map(|h| (read.theta)(&h.state))
        .fold(f64::NAN, f64::max);
    Ok(Measured {
        theta_max,
        period,
        mean_precession: unwrap.total / t_end,
        energy_drift: ((read.energy)(&out.state) - e0).abs() / e0.abs(),
        steps: out.stats.steps,
        seconds: started.elapsed().as_secs_f64(),
    })
}

/// The attitude of an Eulerian state (finite and non-zero: the stepper checks it).
fn attitude(y: &[f64; 7]) -> UnitQuaternion<f64> {
    UnitQuaternion::new_normalize(Quaternion::new(y[0], y[1], y[2], y[3]))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let top = SpinningTop;
    let moments = top.principal().moments;
    let (i1, i3) = (moments[0], moments[2]);
    let mgl = top.mass() * 9.81 * top.center_of_mass().z;
    let (theta0, w3) = (20f64.to_radians(), 150.0);
    println!(
        "Spinning top: M = {:.3} kg, I1 = {i1:.4e}, I3 = {i3:.4e} kg m² about the tip, M g l = {mgl:.4e} N m",
        top.mass()
    );
    let theory = HeavyTopTheory::new(i1, i3, mgl)?;
    println!(
        "Released at rest from θ0 = 20° spinning at ω3 = {w3} rad/s (sleeping threshold {:.1} rad/s)\n",
        theory.sleeping_threshold()
    );
    // The exact nutation: the cubic in u = cos θ, its roots, the period 2K(m)/ν.
    let exact = theory.motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, w3])?;
    let period = exact.nutation_period();
    let t_end = 10.0 * period;

    // 1. DOP853 on the generated angle equations.
    let chart = TopChart::declared(&top);
    let tol = AdaptiveConfig::with_tol(1e-11, 1e-11);
    let mut ode = Dop853::new(&chart, 0.0, [0.0, theta0, 0.0, 0.0, 0.0, w3], tol)?;
    let angle_form = Reading::<[f64; 6]> {
        theta_rate: Box::new(|y| y[4]),
        theta: Box::new(|y| y[1]),
        phi: Box::new(|y| y[0]),
        energy: Box::new(|y| top.energy(&[y[0], y[1], y[2]], &[y[3], y[4], y[5]])),
    };
    let angles = measure("DOP853, generated angle form", &mut ode, t_end, &angle_form)?;

    // 2. DOP853 on the generated Eulerian form (quaternion and ω). The axis is R e3, and
    //    d(cos θ)/dt = (R (ω × e3))·ẑ has the sign of −θ̇.
    let r0 = top.rotation_in(AngleSequence::Zxz, &[0.0, theta0, 0.0]);
    let q0 = UnitQuaternion::from_matrix(&r0);
    let eul = EulerianTop(&top);
    let y0 = EulerianTop::<SpinningTop>::state(&q0, &Vector3::new(0.0, 0.0, w3));
    let inertia = top.inertia();
    let weight_lever = top.center_of_mass() * top.mass() * 9.81;
    let omega = |y: &[f64; 7]| Vector3::new(y[4], y[5], y[6]);
    let eulerian_form = Reading::<[f64; 7]> {
        theta_rate: Box::new(|y| -(attitude(y) * omega(y).cross(&Vector3::z())).z),
        theta: Box::new(|y| (attitude(y) * Vector3::z()).z.acos()),
        phi: Box::new(|y| precession_angle(&(attitude(y) * Vector3::z()))),
        energy: Box::new(|y| {
            let w = omega(y);
            0.5 * w.dot(&(inertia * w)) + (attitude(y) * weight_lever).z
        }),
    };
    let mut ode = Dop853::new(&eul, 0.0, y0, tol)?;
    let eulerian = measure(
        "DOP853, generated Eulerian form",
        &mut ode,
        t_end,
        &eulerian_form,
    )?;

    // 3. Splitting: exact free-body flow plus gravity kicks, 100 steps per nutation period
    //    (each 0.3 spin revolutions long); the principal axes are the description axes here.
    let split = PotentialSplitting {
        free: ExactFreeFlow::new([i1, moments[1], i3])?,
        potential: Gravity {
            weight: top.mass() * 9.81,
            c: top.center_of_mass(),
        },
    };
    let y0 = BodyMomentum {
        q: q0,
        m: Vector3::new(0.0, 0.0, i3 * w3),
    };
    let body_omega = |y: &BodyMomentum| Vector3::new(y.m.x / i1, y.m.y / moments[1], y.m.z / i3);
    let splitting_form = Reading::<BodyMomentum> {
        theta_rate: Box::new(|y| -(y.q * body_omega(y).cross(&Vector3::z())).z),
        theta: Box::new(|y| (y.q * Vector3::z()).z.acos()),
        phi: Box::new(|y| precession_angle(&(y.q * Vector3::z()))),
        energy: Box::new(|y| split.energy(y)),
    };
    let mut stepper =
        FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(period / 100.0))?;
    let splitting = measure(
        "splitting, exact free flow",
        &mut stepper,
        t_end,
        &splitting_form,
    )?;

    // 4. The angle form over 50 000 periods (about 2.8 h of motion): long enough for the
    //    progress bar, and for the period and the energy to show their drift.
    let unbounded = AdaptiveConfig {
        max_steps: u64::MAX,
        ..tol
    };
    let mut ode = Dop853::new(&chart, 0.0, [0.0, theta0, 0.0, 0.0, 0.0, w3], unbounded)?;
    let long = measure(
        "DOP853, angle form, 50 000 periods",
        &mut ode,
        50_000.0 * period,
        &angle_form,
    )?;

    println!(
        "{:<36} {:>14} {:>14} {:>16} {:>11} {:>9} {:>9}",
        "", "amplitude/rad", "period/s", "precession/rad/s", "energy err", "steps", "time/ms"
    );
    println!(
        "{:<36} {:>14.6e} {:>14.8} {:>16.8}",
        "theory (exact nutation)",
        exact.theta_max() - exact.theta_min(),
        period,
        exact.mean_precession_rate()?,
    );
    println!(
        "{:<36} {:>14} {:>14} {:>16.8}",
        "theory (fast-top Mgl/(I3 ω3))",
        "",
        "",
        mgl / (i3 * w3),
    );
    for (name, m) in [
        ("DOP853, generated angle form", &angles),
        ("DOP853, generated Eulerian form", &eulerian),
        ("splitting, exact free flow", &splitting),
        ("DOP853, angle form, 50 000 periods", &long),
    ] {
        println!(
            "{name:<36} {:>14.6e} {:>14.8} {:>16.8} {:>11.1e} {:>9} {:>9.1}",
            m.theta_max - theta0,
            m.period,
            m.mean_precession,
            m.energy_drift,
            m.steps,
            1e3 * m.seconds
        );
    }
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    let mut table = Table::default();
    let amplitude = exact.theta_max() - exact.theta_min();
    table.row(
        "nutation amplitude (rad)",
        angles.theta_max - theta0,
        amplitude,
    );
    table.row("nutation period (s)", angles.period, period);
    let precession = exact.mean_precession_rate()?;
    table.row(
        "mean precession rate (rad/s)",
        angles.mean_precession,
        precession,
    );
    println!(
        "\nAngle form against theory: amplitude {:.1e}, period {:.1e}, precession {:.1e} (relative)",
        rel(
            angles.theta_max - theta0,
            exact.theta_max() - exact.theta_min()
        ),
        rel(angles.period, period),
        rel(angles.mean_precession, exact.mean_precession_rate()?)
    );

    // 5. Figures, one library call each: θ over three nutation periods between the exact
    //    turning angles, and θ against θ̇ (a closed loop, run once a period).
    let mut ode = Dop853::new(&chart, 0.0, [0.0, theta0, 0.0, 0.0, 0.0, w3], tol)?;
    let mut out = Run::new(&mut ode, 3.0 * period)
        .sample_every(period / 200.0)
        .quantities(TopQuantities::new(&top))
        .integrate()?;
    out.trajectory
        .set_state_names(TopQuantities::<SpinningTop>::state_names())?;
    let path = plot::trajectory(
        "heavy_top.svg",
        "Spinning top: nutation θ(t) [rad], DOP853 on the generated angle form",
        &out.trajectory,
        &["theta"],
    )?;
    println!("\nwrote {}", path.display());
    let path = plot::trajectory_phase_portrait(
        "heavy_top_phase.svg",
        "Spinning top: θ̇ against θ over three nutation periods",
        &out.trajectory,
        "theta",
        "theta_dot",
    )?;
    println!("wrote {}", path.display());

    // The same three periods as an animation, ten times slower than life.
    let zxz = |y: &[f64; 6]| {
        UnitQuaternion::from_matrix(&top.rotation_in(AngleSequence::Zxz, &[y[0], y[1], y[2]]))
    };
    let options = animate::Options {
        time_scale: 10.0,
        ..Default::default()
    };
    let movie = animate::top(&top, &out.trajectory, zxz, options)?;
    let caption = "DOP853 on the generated angle form against the exact nutation";
    common::animation::write_animation(
        &plot_dir()?,
        "heavy_top",
        "Heavy top",
        &movie,
        &table,
        caption,
    )?;
    Ok(())
}
