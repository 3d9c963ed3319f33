//! The symbolic half: the Lagrangian of the four bodies, the rolling constraints and the
//! front wheel's contact, built with precess's symbolic engine.
//!
//! Frames follow the benchmark paper: x forward, y to the right, z down, the origin at the
//! rear contact. Every position is written in the yaw frame (the ground frame turned by the
//! yaw ψ), so the yaw enters only through the rear contact's rates
//! (ẋ cos ψ + ẏ sin ψ, −ẋ sin ψ + ẏ cos ψ): the expansions stay small and nothing in them
//! depends on where on the ground the bicycle is.

use precess::lagrange::{Constraints, Coordinates, EquationsOfMotion, LagrangeError};
use precess::sym::mat3::{Mat3, cross, dot, mat_mul, mat_vec, transpose};
use precess::sym::{Arena, ExprId};

/// What the derivation hands to the numerical side.
pub(super) struct Derived {
    pub coords: Coordinates,
    pub eom: EquationsOfMotion,
    pub constraints: Constraints,
    /// `Ȧ q̇`, one per constraint row.
    pub rate_terms: Vec<ExprId>,
    /// T + V.
    pub energy: ExprId,
    /// The material velocities of the rear and the front contact points (yaw frame).
    pub contact_velocities: [ExprId; 6],
}

type Vec3 = [ExprId; 3];

fn rot_x(a: &Arena, c: ExprId, s: ExprId, ms: ExprId) -> Mat3 {
    let (o, z) = (a.one(), a.zero());
    [[o, z, z], [z, c, ms], [z, s, c]]
}

fn rot_y(a: &Arena, c: ExprId, s: ExprId, ms: ExprId) -> Mat3 {
    let (o, z) = (a.one(), a.zero());
    [[c, z, s], [z, o, z], [ms, z, c]]
}

fn rot_z(a: &Arena, c: ExprId, s: ExprId, ms: ExprId) -> Mat3 {
    let (o, z) = (a.one(), a.zero());
    [[c, ms, z], [s, c, z], [z, z, o]]
}

/// The elementary rotation about axis 0, 1 or 2 by the angle `q`.
fn rot(a: &mut Arena, axis: usize, q: ExprId) -> Mat3 {
    let (c, s) = (a.cos(q), a.sin(q));
    let ms = a.neg(s);
    match axis {
        0 => rot_x(a, c, s, ms),
        1 => rot_y(a, c, s, ms),
        _ => rot_z(a, c, s, ms),
    }
}

fn add3(a: &mut Arena, u: &Vec3, v: &Vec3) -> Vec3 {
    [a.add(u[0], v[0]), a.add(u[1], v[1]), a.add(u[2], v[2])]
}

fn sub3(a: &mut Arena, u: &Vec3, v: &Vec3) -> Vec3 {
    [a.sub(u[0], v[0]), a.sub(u[1], v[1]), a.sub(u[2], v[2])]
}

fn scale3(a: &mut Arena, k: ExprId, v: &Vec3) -> Vec3 {
    [a.mul(k, v[0]), a.mul(k, v[1]), a.mul(k, v[2])]
}

fn expand3(a: &mut Arena, v: &Vec3) -> Vec3 {
    [a.expand(v[0]), a.expand(v[1]), a.expand(v[2])]
}

/// The angular velocity after one more elementary rotation, in the new body's axes:
/// ω' = Eᵀ ω + q̇ e_axis.
fn turn(a: &mut Arena, omega: &Vec3, e: &Mat3, axis: usize, rate: ExprId) -> Vec3 {
    let et = transpose(e);
    let mut w = mat_vec(a, &et, omega);
    w[axis] = a.add(w[axis], rate);
    expand3(a, &w)
}

/// ½ ωᵀ I ω for I = [[xx, 0, xz], [0, yy, 0], [xz, 0, zz]].
fn rotational(a: &mut Arena, half: ExprId, w: &Vec3, i: [ExprId; 4]) -> ExprId {
    let [xx, yy, zz, xz] = i;
    let two = a.integer(2);
    let w00 = a.mul(w[0], w[0]);
    let w11 = a.mul(w[1], w[1]);
    let w22 = a.mul(w[2], w[2]);
    let t0 = a.mul(xx, w00);
    let t1 = a.mul(yy, w11);
    let t2 = a.mul(zz, w22);
    let t3 = a.product(&[two, xz, w[0], w[2]]);
    let s = a.sum(&[t0, t1, t2, t3]);
    a.mul(half, s)
}

/// The symbolic bicycle. Coordinates in the order
/// `x, y, psi, phi, theta, delta, theta_r, theta_f`.
pub(super) fn derive(a: &mut Arena) -> Result<Derived, LagrangeError> {
    let c = Coordinates::new(
        a,
        &[
            "x", "y", "psi", "phi", "theta", "delta", "theta_r", "theta_f",
        ],
    );
    let [x_d, y_d, psi_d, phi_d, theta_d, delta_d, thr_d, thf_d] =
        [0, 1, 2, 3, 4, 5, 6, 7].map(|i| c.rates[i]);
    let (psi, phi, theta, delta) = (c.q[2], c.q[3], c.q[4], c.q[5]);
    let p = |a: &mut Arena, n: &str| a.parameter(n);
    let (w, trail, lambda, g) = (p(a, "w"), p(a, "c"), p(a, "lambda"), p(a, "g"));
    let (r_r, m_r, i_rxx, i_ryy) = (p(a, "rR"), p(a, "mR"), p(a, "IRxx"), p(a, "IRyy"));
    let (x_b, z_b, m_b) = (p(a, "xB"), p(a, "zB"), p(a, "mB"));
    let (i_bxx, i_byy, i_bzz, i_bxz) = (p(a, "IBxx"), p(a, "IByy"), p(a, "IBzz"), p(a, "IBxz"));
    let (x_h, z_h, m_h) = (p(a, "xH"), p(a, "zH"), p(a, "mH"));
    let (i_hxx, i_hyy, i_hzz, i_hxz) = (p(a, "IHxx"), p(a, "IHyy"), p(a, "IHzz"), p(a, "IHxz"));
    let (r_f, m_f, i_fxx, i_fyy) = (p(a, "rF"), p(a, "mF"), p(a, "IFxx"), p(a, "IFyy"));
    let zero = a.zero();

    // Orientations, relative to the yaw frame, and angular velocities in body axes.
    let roll = rot(a, 0, phi);
    let pitch = rot(a, 1, theta);
    let frame_b = mat_mul(a, &roll, &pitch);
    let omega_yaw = [zero, zero, psi_d];
    let omega_roll = turn(a, &omega_yaw, &roll, 0, phi_d);
    let omega_b = turn(a, &omega_roll, &pitch, 1, theta_d);
    // The steer axis s = R_y(λ) ẑ, tilted back by λ; steering turns H about it:
    // R_s(δ) = R_y(λ) R_z(δ) R_y(λ)ᵀ, so ω_H = R_sᵀ ω_B + δ̇ s.
    let tilt = rot(a, 1, lambda);
    let steer_z = rot(a, 2, delta);
    let ts = mat_mul(a, &tilt, &steer_z);
    let steer = mat_mul(a, &ts, &transpose(&tilt));
    let steer = steer.map(|row| row.map(|e| a.expand(e)));
    let axis = [a.sin(lambda), zero, a.cos(lambda)];
    let mut omega_h = mat_vec(a, &transpose(&steer), &omega_b);
    for k in [0, 2] {
        let t = a.mul(delta_d, axis[k]);
        omega_h[k] = a.add(omega_h[k], t);
    }
    let omega_h = expand3(a, &omega_h);
    let frame_h = mat_mul(a, &frame_b, &steer);
    let frame_h = frame_h.map(|row| row.map(|e| a.expand(e)));

    // Positions in the yaw frame relative to the rear contact.
    let minus_rr = a.neg(r_r);
    let hub_r_body = [zero, zero, minus_rr];
    let hub_r = mat_vec(a, &roll, &hub_r_body);
    let hub_r = expand3(a, &hub_r);
    let in_b = |a: &mut Arena, pt: &Vec3| {
        let rel = sub3(a, pt, &hub_r_body);
        let turned = mat_vec(a, &frame_b, &rel);
        let out = add3(a, &hub_r, &turned);
        expand3(a, &out)
    };
    let wc = a.add(w, trail);
    let steer_foot = [wc, zero, zero];
    let foot = in_b(a, &steer_foot);
    let in_h = |a: &mut Arena, pt: &Vec3| {
        let rel = sub3(a, pt, &steer_foot);
        let turned = mat_vec(a, &frame_h, &rel);
        let out = add3(a, &foot, &turned);
        expand3(a, &out)
    };
    let com_b = in_b(a, &[x_b, zero, z_b]);
    let com_h = in_h(a, &[x_h, zero, z_h]);
    let minus_rf = a.neg(r_f);
    let hub_f = in_h(a, &[w, zero, minus_rf]);

    // Velocities in the yaw frame: the rear contact's, turned into it, plus ṗ + ψ̇ ẑ × p.
    let (cpsi, spsi) = (a.cos(psi), a.sin(psi));
    let vx0 = {
        let t0 = a.mul(x_d, cpsi);
        let t1 = a.mul(y_d, spsi);
        a.add(t0, t1)
    };
    let vy0 = {
        let t0 = a.mul(y_d, cpsi);
        let t1 = a.mul(x_d, spsi);
        a.sub(t0, t1)
    };
    let velocity = |a: &mut Arena, pos: &Vec3| -> Vec3 {
        let dp = pos.map(|e| a.dt(e));
        let yaw = cross(a, &[zero, zero, psi_d], pos);
        let base = [vx0, vy0, zero];
        let v = add3(a, &dp, &yaw);
        let v = add3(a, &v, &base);
        expand3(a, &v)
    };
    let v_r = velocity(a, &hub_r);
    let v_b = velocity(a, &com_b);
    let v_h = velocity(a, &com_h);
    let v_f = velocity(a, &hub_f);

    // Kinetic energy: each wheel is axisymmetric about its axle y, so its spin angle drops
    // out and its ω is the carrier's (roll frame for R, H for F) plus the spin rate on y.
    let half = a.number("0.5")?;
    let translational = |a: &mut Arena, m: ExprId, v: &Vec3| {
        let v2 = dot(a, v, v);
        a.product(&[half, m, v2])
    };
    let mut omega_rw = omega_roll;
    omega_rw[1] = a.add(omega_rw[1], thr_d);
    let mut omega_fw = omega_h;
    omega_fw[1] = a.add(omega_fw[1], thf_d);
    let kinetic = [
        translational(a, m_r, &v_r),
        rotational(a, half, &omega_rw, [i_rxx, i_ryy, i_rxx, zero]),
        translational(a, m_b, &v_b),
        rotational(a, half, &omega_b, [i_bxx, i_byy, i_bzz, i_bxz]),
        translational(a, m_h, &v_h),
        rotational(a, half, &omega_h, [i_hxx, i_hyy, i_hzz, i_hxz]),
        translational(a, m_f, &v_f),
        rotational(a, half, &omega_fw, [i_fxx, i_fyy, i_fxx, zero]),
    ];
    let t = a.sum(&kinetic);
    // z points down: the potential is −g Σ m z.
    let weights = [
        a.mul(m_r, hub_r[2]),
        a.mul(m_b, com_b[2]),
        a.mul(m_h, com_h[2]),
        a.mul(m_f, hub_f[2]),
    ];
    let mz = a.sum(&weights);
    let v = a.mul(g, mz);
    let v = a.neg(v);
    let lagrangian = a.sub(t, v);
    let lagrangian = a.expand(lagrangian);
    let energy = a.add(t, v);
    let energy = a.expand(energy);
    let zeros = vec![zero; 8];
    let eom = EquationsOfMotion::derive(a, lagrangian, c.clone(), &zeros)?;

    // Rear contact: hub − r_R (roll-frame ẑ) is straight below the hub; its material
    // velocity v_hub + ω_R × (contact − hub), with ω_R in yaw axes.
    let omega_rw_yaw = mat_vec(a, &roll, &omega_rw);
    let minus_hub_r = hub_r.map(|e| a.neg(e));
    let spin_r = cross(a, &omega_rw_yaw, &minus_hub_r);
    let slip_r = add3(a, &v_r, &spin_r);
    let slip_r = expand3(a, &slip_r);

    // Front contact: the rim point lowest along z, hub + r_F d/|d| with d = ẑ − n_z n, n the
    // axle; |d| = √(1 − n_z²). It touches the ground when hub_z + r_F √(1 − n_z²) = 0.
    let n = [frame_h[0][1], frame_h[1][1], frame_h[2][1]];
    let nz2 = a.mul(n[2], n[2]);
    let one = a.one();
    let d2 = a.sub(one, nz2);
    let d2 = a.expand(d2);
    let dn = a.sqrt(d2)?;
    let minus_nz = a.neg(n[2]);
    let dvec = [
        a.mul(minus_nz, n[0]),
        a.mul(minus_nz, n[1]),
        a.sub(one, nz2),
    ];
    let rf_over = a.div(r_f, dn)?;
    let arm = scale3(a, rf_over, &dvec);
    let arm = expand3(a, &arm);
    let lift = a.mul(r_f, dn);
    let contact_z = a.add(hub_f[2], lift);
    let omega_fw_yaw = mat_vec(a, &frame_h, &omega_fw);
    let spin_f = cross(a, &omega_fw_yaw, &arm);
    let slip_f = add3(a, &v_f, &spin_f);
    let slip_f = expand3(a, &slip_f);

    let mut k = Constraints::new();
    let row_of = |a: &mut Arena, k: &mut Constraints, e: ExprId| {
        let row: Vec<ExprId> = c
            .rates
            .iter()
            .map(|&r| {
                let s = a
                    .as_symbol(r)
                    .unwrap_or_else(|| unreachable!("rates are symbols"));
                let d = a.diff(e, s);
                a.expand(d)
            })
            .collect();
        k.nonholonomic(a, &c, &row, zero).map(|_| ())
    };
    row_of(a, &mut k, slip_r[0])?;
    row_of(a, &mut k, slip_r[1])?;
    k.holonomic(a, &c, contact_z)?;
    row_of(a, &mut k, slip_f[0])?;
    row_of(a, &mut k, slip_f[1])?;
    let rate_terms = k.rate_terms(a, &c);
    Ok(Derived {
        coords: c,
        eom,
        constraints: k,
        rate_terms,
        energy,
        contact_velocities: [
            slip_r[0], slip_r[1], slip_r[2], slip_f[0], slip_f[1], slip_f[2],
        ],
    })
}
