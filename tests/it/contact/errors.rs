//! Bad input to the contact scene: each refused with a typed error naming the quantity and
//! its value.

use nalgebra::{UnitQuaternion, Vector3};
use precess::codegen::BindingError;
use precess::contact::{ContactDynamics, ContactError, ContactRun, Phase};
use precess::ode::AdaptiveConfig;

use super::reference::{
    NumBody, NumLaw, NumSurface, ROLLING, model, offset_sphere, rattleback, state, thin_disk,
    try_model,
};

fn err(body: &NumBody, law: NumLaw) -> ContactError {
    try_model(body, law).expect_err("the model was accepted")
}

#[test]
fn friction_coefficients_must_be_finite_and_not_negative() {
    let b = offset_sphere();
    assert_eq!(
        err(&b, NumLaw::Coulomb(-0.1)),
        ContactError::NegativeCoefficient {
            name: "mu",
            value: -0.1
        }
    );
    assert_eq!(
        err(&b, NumLaw::StickSlip(-2.0)),
        ContactError::NegativeCoefficient {
            name: "mu",
            value: -2.0
        }
    );
    assert_eq!(
        err(&b, NumLaw::Viscous(-1e-3)),
        ContactError::NegativeCoefficient {
            name: "viscous",
            value: -1e-3
        }
    );
    assert_eq!(
        err(
            &b,
            NumLaw::Rolling {
                cr: Some(-1.0),
                cs: None
            }
        ),
        ContactError::NegativeCoefficient {
            name: "rolling_resistance",
            value: -1.0
        }
    );
    // NaN never reaches the model: the binding refuses it by name.
    assert!(matches!(
        err(&b, NumLaw::Coulomb(f64::NAN)),
        ContactError::Binding(BindingError::NonFinite { ref name, .. }) if name == "mu"
    ));
    // Set later, the rule is checked again.
    let mut m = model(&b, NumLaw::Coulomb(0.3));
    assert_eq!(
        m.set("mu", -0.5).err(),
        Some(ContactError::NegativeCoefficient {
            name: "mu",
            value: -0.5
        })
    );
    // The refused value is undone: the model still has μ = 0.3.
    assert_eq!(m.friction_coefficient(), Some(0.3));
    m.set("mu", 0.4).unwrap();
    assert_eq!(m.friction_coefficient(), Some(0.4));
}

#[test]
fn surfaces_must_be_convex_with_the_centre_of_mass_inside() {
    let mut b = offset_sphere();
    b.center = [0.0, 0.0, -0.03];
    assert_eq!(
        err(&b, ROLLING),
        ContactError::CenterOutsideSurface {
            surface: "sphere",
            center: [0.0, 0.0, -0.03],
            measure: 1.5,
        }
    );
    let mut r = rattleback();
    r.center = [0.0, 0.0, 0.04];
    assert!(matches!(
        err(&r, ROLLING),
        ContactError::CenterOutsideSurface { surface: "ellipsoid", measure, .. } if (measure - 1.5).abs() < 1e-12
    ));
    let mut torus = thin_disk();
    torus.surface = NumSurface::Torus {
        c: [0.0; 3],
        big: 0.05,
        tube: 0.06,
    };
    assert!(matches!(
        err(&torus, ROLLING),
        ContactError::BadSurface { surface: "torus", name: "tube", value, .. } if value == 0.06
    ));
    let mut neg = thin_disk();
    neg.surface = NumSurface::DiskRim {
        c: [0.0; 3],
        rho: -0.1,
    };
    assert!(matches!(
        err(&neg, ROLLING),
        ContactError::BadSurface { surface: "disk_rim", name: "radius", value, .. } if value == -0.1
    ));
    let mut bowl = offset_sphere();
    bowl.surface = NumSurface::Paraboloid {
        v: [0.0, 0.0, 0.0],
        big: 0.1,
    };
    // The centre of mass 6 mm below the vertex is outside the bowl.
    assert!(matches!(
        err(&bowl, ROLLING),
        ContactError::CenterOutsideSurface {
            surface: "paraboloid",
            ..
        }
    ));
}

#[test]
fn mass_gravity_and_inertia_are_checked() {
    let mut b = offset_sphere();
    b.mass = -1.0;
    assert_eq!(
        err(&b, ROLLING),
        ContactError::BadParameter {
            name: "mass",
            value: -1.0,
            rule: "finite and > 0"
        }
    );
    let mut b = offset_sphere();
    b.gravity = -9.81;
    assert!(
        matches!(err(&b, ROLLING), ContactError::BadParameter { name: "gravity", value, .. } if value == -9.81)
    );
    let mut b = offset_sphere();
    b.inertia[2][2] = -1e-6;
    assert!(matches!(err(&b, ROLLING), ContactError::Body(_)));
}

#[test]
fn states_are_checked() {
    let m = model(&offset_sphere(), ROLLING);
    let good = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(1.0, 2.0, 3.0),
        )
        .unwrap();
    assert_eq!(m.check_state(Phase::Rolling, &good), Ok(()));
    // Not derived: a rolling body has no sliding equations.
    assert_eq!(
        m.check_state(Phase::Sliding, &good),
        Err(ContactError::PhaseNotDerived {
            phase: Phase::Sliding,
            law: "rolling"
        })
    );
    let mut nan = good;
    nan[9] = f64::NAN;
    assert!(matches!(
        m.check_state(Phase::Rolling, &nan),
        Err(ContactError::NonFinite {
            quantity: "omega",
            ..
        })
    ));
    let mut zero = good;
    zero[4..8].copy_from_slice(&[0.0; 4]);
    assert!(matches!(
        m.check_state(Phase::Rolling, &zero),
        Err(ContactError::BadQuaternion { norm, .. }) if norm == 0.0
    ));
    let mut long = good;
    long[4] = 1.001;
    assert!(matches!(
        m.check_state(Phase::Rolling, &long),
        Err(ContactError::BadQuaternion { .. })
    ));
    // Slipping while the law says rolling: 1 mm/s off.
    let mut slipping = good;
    slipping[3] += 1e-3;
    let e = m.check_state(Phase::Rolling, &slipping).unwrap_err();
    let ContactError::RollingConstraint { slip, .. } = e else {
        panic!("{e:?}");
    };
    assert!((slip - 1e-3).abs() < 1e-12, "{slip}");
    // The run refuses it too.
    assert!(matches!(
        ContactRun::new(&m, Phase::Rolling, 0.0, slipping, AdaptiveConfig::default()),
        Err(ContactError::RollingConstraint { .. })
    ));
    // Checked accelerations agree with the unchecked ones on a good state.
    let mut d = [0.0; 11];
    m.phase_rhs(Phase::Rolling, 0.0, &good, &mut d);
    assert_eq!(m.accelerations(Phase::Rolling, 0.0, &good), Ok(d));
}

#[test]
fn singular_contacts_are_refused() {
    let disk = model(&thin_disk(), ROLLING);
    let flat = state(
        [0.0, 0.0],
        [0.0, 0.0],
        &UnitQuaternion::identity(),
        &Vector3::zeros(),
    );
    assert!(matches!(
        disk.check_state(Phase::Rolling, &flat),
        Err(ContactError::FlatDisk { surface: "disk_rim", tilt, .. }) if tilt == 0.0
    ));
    let bowl = NumBody {
        mass: 0.3,
        center: [0.0, 0.0, 0.05],
        inertia: [[4e-4, 0.0, 0.0], [0.0, 5e-4, 0.0], [0.0, 0.0, 3e-4]],
        surface: NumSurface::Paraboloid {
            v: [0.0; 3],
            big: 0.2,
        },
        gravity: 9.81,
    };
    let bowl = model(&bowl, NumLaw::Frictionless);
    let over = UnitQuaternion::from_euler_angles(1.7, 0.0, 0.0);
    let y = state([0.0, 0.0], [0.0, 0.0], &over, &Vector3::zeros());
    assert!(matches!(
        bowl.check_state(Phase::Sliding, &y),
        Err(ContactError::PastParaboloidRim { n3, .. }) if n3 > 0.0
    ));
}

/// Coulomb sliding with the slip stopped has no friction direction: the checked
/// accelerations say so instead of returning NaN.
#[test]
fn coulomb_sliding_without_slip_is_not_finite() {
    let m = model(&offset_sphere(), NumLaw::Coulomb(0.3));
    let rolling_like = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(1.0, 0.0, 0.0),
        )
        .unwrap();
    assert!(matches!(
        m.accelerations(Phase::Sliding, 0.5, &rolling_like),
        Err(ContactError::NonFiniteResult { phase: Phase::Sliding, t, .. }) if t == 0.5
    ));
}
