//! The loads of a body's joint (springs, dampers, efforts, user functions) and the
//! mechanism's settings (gravity, route), each value checked as `#[rigid]` values are.

use precess_core::mechanism::{CoordinateLoad, Route, Spring};
use precess_core::sym::ExprId;
use syn::Expr;

use super::check::{LinkKeys, UserEffort};
use super::joint::path_ident;
use crate::lang::check::Checker;
use crate::lang::keys;
use crate::lang::units::Dim;

/// What one coordinate of a joint measures: the dimensions its loads take follow from it.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Coordinate {
    /// An angle (revolute, universal, spherical, a free joint's rotations): spring in N m/rad,
    /// damper in N m s, effort a torque, rest an angle.
    Angle,
    /// A length (prismatic, a free joint's translations): spring in N/m, damper in N s/m,
    /// effort a force, rest a length.
    Length,
}

impl Coordinate {
    fn stiffness(self) -> Dim {
        match self {
            Coordinate::Angle => Dim::ROTARY_STIFFNESS,
            Coordinate::Length => Dim::STIFFNESS,
        }
    }

    /// How an error names the stiffness: a torque per radian (`N m` alone is taken as per
    /// radian, as SI's radian is 1).
    fn stiffness_name(self) -> Option<&'static str> {
        match self {
            Coordinate::Angle => Some("a rotary stiffness (N m per rad)"),
            Coordinate::Length => None,
        }
    }

    fn damper(self) -> Dim {
        match self {
            Coordinate::Angle => Dim::ROTARY_DAMPING,
            Coordinate::Length => Dim::DRAG,
        }
    }

    fn effort(self) -> Dim {
        match self {
            Coordinate::Angle => Dim::TORQUE,
            Coordinate::Length => Dim::FORCE,
        }
    }

    fn rest(self) -> Dim {
        match self {
            Coordinate::Angle => Dim::ANGLE,
            Coordinate::Length => Dim::LENGTH,
        }
    }
}

impl Checker<'_> {
    /// The loads of a joint's coordinates: spring, damper and effort, one value each per
    /// coordinate (`[a, b]` for a joint of two), each in the dimension its coordinate's kind
    /// gives it (a value with units in another is a spanned error).
    pub(super) fn loads(
        &mut self,
        k: &LinkKeys,
        coordinates: &[Coordinate],
        efforts: &mut Vec<UserEffort>,
    ) -> Option<Vec<CoordinateLoad>> {
        let dof = coordinates.len();
        let mut loads = vec![CoordinateLoad::default(); dof];
        let mut ok = true;
        if let Some(e) = k.damper {
            match self.per_coordinate(e, dof, keys::DAMPER) {
                Some(values) => {
                    for ((load, v), c) in loads.iter_mut().zip(values).zip(coordinates) {
                        load.damper = self.expecting(c.damper(), keys::DAMPER, |ck| {
                            let why = Some("a negative one feeds energy in");
                            ck.non_negative(v, &format!("`{}`", keys::DAMPER), why)
                        });
                        ok &= load.damper.is_some();
                    }
                }
                None => ok = false,
            }
        }
        if let Some(e) = k.effort {
            match self.per_coordinate(e, dof, keys::EFFORT) {
                Some(values) => {
                    for ((load, v), c) in loads.iter_mut().zip(values).zip(coordinates) {
                        load.effort =
                            self.expecting(c.effort(), keys::EFFORT, |ck| ck.effort(v, efforts));
                        ok &= load.effort.is_some();
                    }
                }
                None => ok = false,
            }
        }
        if let Some((name, list)) = k.spring {
            let mut stiffness = None;
            let mut rest = None;
            for kv in list {
                let slot = match kv.key.to_string().as_str() {
                    keys::STIFFNESS => &mut stiffness,
                    keys::REST => &mut rest,
                    _ => {
                        let place = format!("for `{}`", keys::SPRING);
                        let known = [keys::STIFFNESS, keys::REST];
                        let message = keys::unknown_key(&kv.key, &place, &known, &[]);
                        self.cx.error_spanned_by(&kv.key, message);
                        ok = false;
                        continue;
                    }
                };
                if slot.is_some() {
                    self.cx.error_spanned_by(
                        &kv.key,
                        format!("duplicate key `{}` in `{}`", kv.key, keys::SPRING),
                    );
                    ok = false;
                }
                *slot = Some(&kv.value);
            }
            match stiffness {
                None => {
                    self.cx.error_spanned_by(
                        name,
                        format!(
                            "`{}` needs its stiffness `{} = ..` (the rest value defaults to 0)",
                            keys::SPRING,
                            keys::STIFFNESS
                        ),
                    );
                    ok = false;
                }
                Some(ke) => {
                    let ks = self.per_coordinate(ke, dof, keys::STIFFNESS);
                    let rests = match rest {
                        Some(r) => self.per_coordinate(r, dof, keys::REST),
                        None => None,
                    };
                    match ks {
                        Some(ks) => {
                            for (i, ((load, kv), c)) in
                                loads.iter_mut().zip(ks).zip(coordinates).enumerate()
                            {
                                let stiffness = self.expecting_as(
                                    c.stiffness(),
                                    c.stiffness_name(),
                                    keys::STIFFNESS,
                                    |ck| {
                                        ck.non_negative(kv, &format!("`{}`", keys::STIFFNESS), None)
                                    },
                                );
                                let rest = match (&rests, rest) {
                                    (Some(r), _) => r.get(i).and_then(|&r| {
                                        self.expecting(c.rest(), keys::REST, |ck| ck.scalar(r))
                                    }),
                                    (None, None) => Some(self.arena.zero()),
                                    (None, Some(_)) => None,
                                };
                                match (stiffness, rest) {
                                    (Some(stiffness), Some(rest)) => {
                                        load.spring = Some(Spring { stiffness, rest });
                                    }
                                    _ => ok = false,
                                }
                            }
                        }
                        None => ok = false,
                    }
                }
            }
        }
        ok.then_some(loads)
    }

    /// The values of a load key, one per coordinate.
    pub(super) fn per_coordinate<'e>(
        &mut self,
        e: &'e Expr,
        dof: usize,
        key: &str,
    ) -> Option<Vec<&'e Expr>> {
        if dof == 1 {
            return Some(vec![e]);
        }
        match e {
            Expr::Array(a) if a.elems.len() == dof => Some(a.elems.iter().collect()),
            _ => {
                self.cx.error_spanned_by(
                    e,
                    format!("`{key}` of a joint with {dof} coordinates takes one value per coordinate, `[{}]`", vec!["..";dof].join(", ")),
                );
                None
            }
        }
    }

    /// An effort: a value, or the path of a function `f(&self, t, &q, &qdot) -> f64`. A
    /// single name is a field when the struct has one by that name, else a function.
    pub(super) fn effort(&mut self, e: &Expr, efforts: &mut Vec<UserEffort>) -> Option<ExprId> {
        let function = match e {
            Expr::Path(p) if p.qself.is_none() => match p.path.get_ident() {
                Some(i) => self.input.field(i).is_none(),
                None => true,
            },
            _ => false,
        };
        if !function {
            return self.scalar(e);
        }
        let Expr::Path(p) = e else { return None };
        let index = efforts.len();
        let symbol = self.arena.input(&format!("effort_user_{index}"));
        efforts.push(UserEffort {
            path: p.path.clone(),
            symbol,
            index,
        });
        Some(symbol)
    }

    /// `gravity = g` (along −z) or `[gx, gy, gz]`, an acceleration.
    pub(super) fn gravity(&mut self, e: &Expr) -> Option<[ExprId; 3]> {
        if let Expr::Array(_) = e {
            return self.expecting(Dim::ACCELERATION, keys::GRAVITY, |ck| ck.vector(e));
        }
        let g = self.expecting(Dim::ACCELERATION, keys::GRAVITY, |ck| ck.scalar(e))?;
        let z = self.arena.zero();
        Some([z, z, self.arena.neg(g)])
    }

    pub(super) fn route(&mut self, e: &Expr) -> Route {
        match path_ident(e).and_then(|i| Route::from_name(&i.to_string())) {
            Some(route) => route,
            None => {
                self.cx.error_spanned_by(
                    e,
                    format!(
                        "`{}` expects one of {}",
                        keys::ROUTE,
                        keys::ROUTES.join(", ")
                    ),
                );
                Route::Auto
            }
        }
    }
}
