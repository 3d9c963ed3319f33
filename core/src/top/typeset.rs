//! A top's equations typeset for a reader and the cost of the code `#[top]` generates: the
//! one function behind both a derived struct's [`super::TopDynamics::equations`] (the macro
//! calls it while it expands) and the run-time [`TopScene::typeset`].

use std::borrow::Cow;

use super::derivation::TopDerivation;
use super::scene::TopScene;
use crate::codegen::decimal;
use crate::codegen::{Lines, MethodCost, Paper, Program, Typeset};
use crate::lagrange::LagrangeError;
use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId, SymbolId, SymbolKind};

impl TopScene {
    /// The scene's equations in paper form (grouped by parameter, sin² θ where it prints
    /// shorter, one string per equation) with the operation counts of the code `#[top]`
    /// generates for the declared angle sequence: what a derived struct with the same
    /// description returns from [`super::TopDynamics::equations`], string for string.
    ///
    /// The lines are L = T − V; `Σⱼ Mᵢⱼ q̈ⱼ = fᵢ` per coordinate; q̈ᵢ; the conserved momenta;
    /// the definitions of the abbreviated mass properties they name. The costs are those
    /// of `accelerations_unchecked`, `angle_jacobian`, `energy`, `conserved_momenta`, `rotation_in`,
    /// `rate_matrix_in` (for [`TopScene::sequence`]) and `eulerian_rhs`, not counting a
    /// call to a user torque function.
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// use precess_core::top::TopScene;
    ///
    /// let mut a = Arena::new();
    /// let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
    /// let z = a.zero();
    /// let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i1, z], [z, z, i3]]);
    /// scene.mass = a.parameter("M");
    /// scene.center = [z, z, a.parameter("l")];
    /// scene.gravity = Some(a.parameter("g"));
    /// let eq = scene.typeset(&mut a)?;
    /// assert_eq!(
    ///     eq.lagrangian,
    ///     r"L = \frac{1}{2} I_{1} \left(\dot{\theta}^{2} + \dot{\phi}^{2} \sin^{2}\theta\right) + \frac{1}{2} I_{3} \left(\dot{\psi} + \dot{\phi} \cos\theta\right)^{2} - M g l \cos\theta"
    /// );
    /// assert_eq!(eq.conserved[1], r"p_{\psi} = I_{3} \left(\dot{\psi} + \dot{\phi} \cos\theta\right)");
    /// # Ok::<(), precess_core::lagrange::LagrangeError>(())
    /// ```
    ///
    /// # Errors
    /// As [`TopScene::derive`] and [`TopScene::eulerian_rhs`].
    pub fn typeset(&self, arena: &mut Arena) -> Result<Typeset, LagrangeError> {
        let attitude: Mat3 =
            std::array::from_fn(|i| std::array::from_fn(|j| arena.input(&format!("R{i}{j}"))));
        let omega = [arena.input("w0"), arena.input("w1"), arena.input("w2")];
        self.typeset_reading(arena, &attitude, &omega)
    }

    /// [`TopScene::typeset`], the Eulerian form counted as the program over the given
    /// symbols for the attitude matrix (body to space) and ω.
    ///
    /// The operation count of generated code depends on the order its expressions were
    /// built in (the canonical order of a sum is the order its terms were made, and lowering
    /// follows it), so the derive passes the very symbols its `eulerian_rhs` reads: the
    /// count is then of the program it emitted. The angle-form expressions need no such
    /// care: rebuilt in the same arena they are the same expressions.
    ///
    /// # Errors
    /// As [`TopScene::typeset`].
    pub fn typeset_reading(
        &self,
        arena: &mut Arena,
        attitude: &Mat3,
        omega: &[ExprId; 3],
    ) -> Result<Typeset, LagrangeError> {
        let top = self.derive(arena)?;
        let costs = self.costs(arena, &top, attitude, omega)?;
        // The lines are printed from the scene with its constant mass properties named (the
        // costs above are of the code, which uses the constants).
        let (named, values) = self.named(arena);
        let top = if values.is_empty() {
            top
        } else {
            named.derive(arena)?
        };
        let lagrangian = top.lagrangian(arena);
        let c = top.coords().clone();
        let mut equations = Vec::with_capacity(c.len());
        for (row, &f) in top.equations.mass.iter().zip(&top.equations.forcing) {
            let products: Vec<ExprId> = row
                .iter()
                .zip(&c.accels)
                .map(|(&m, &a)| arena.mul(m, a))
                .collect();
            equations.push((arena.sum(&products), f));
        }
        let paper = self.paper(arena);
        let lagrangian = format!("L = {}", paper.latex(lagrangian));
        let equations = equations
            .into_iter()
            .map(|(lhs, rhs)| paper.equation(lhs, rhs))
            .collect();
        let accelerations = c
            .accels
            .iter()
            .zip(&top.accelerations.accel)
            .map(|(&q_ddot, &value)| {
                format!("{} = {}", latex_of(arena, q_ddot), paper.latex(value))
            })
            .collect();
        let conserved: Vec<String> =
            c.q.iter()
                .zip(&top.conserved_momenta)
                .filter_map(|(&q, p)| {
                    let p = (*p)?;
                    Some(format!("p_{{{}}} = {}", latex_of(arena, q), paper.latex(p)))
                })
                .collect();
        let mut definitions = definitions(arena, &paper, &top);
        definitions.extend(
            values
                .iter()
                .map(|(symbol, v)| format!("{symbol} = {}", decimal(*v, VALUE_DIGITS))),
        );
        let values = values
            .into_iter()
            .map(|(symbol, v)| (Cow::Owned(symbol), Cow::Owned(format!("{v:?}"))))
            .collect();
        Ok(Typeset {
            lagrangian: Cow::Owned(lagrangian),
            equations: owned(equations),
            accelerations: owned(accelerations),
            conserved: owned(conserved),
            definitions: owned(definitions),
            values: Cow::Owned(values),
            costs: Cow::Owned(costs),
        })
    }

    /// This scene with its constant mass properties and gravity replaced by parameters named
    /// as a textbook names them, and the LaTeX and value of each name, in order of name.
    ///
    /// A body of literal parts has exact rationals of twenty digits for mass properties
    /// (values given in units or with π are f64s made exact), which would print in every
    /// term. Named: the moments I₁, I₂, I₃ of a diagonal tensor (one name for equal moments,
    /// so a symmetric top reads I₁, I₃), else the entries I_xx … of the tensor; the mass M;
    /// the distance l of a centre on the z axis, else its components c_x, c_y, c_z; gravity
    /// g. Zeros stay zeros. For a body that depends on fields only a constant that prints
    /// long is named (a literal `0.01` among fields stays as typed). A name some symbol of
    /// the arena already has is primed.
    fn named(&self, arena: &mut Arena) -> (TopScene, Vec<(String, f64)>) {
        let t = self.inertia;
        let props = t.iter().flatten().chain(&self.center).chain([&self.mass]);
        let literal = props.clone().all(|&e| arena.free_symbols(e).is_empty());
        let mut namer = Namer {
            literal,
            values: Vec::new(),
        };
        let mut scene = self.clone();
        let diagonal = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .all(|&(i, j)| arena.as_rational(t[i][j]).is_some_and(|r| r.is_zero()));
        if diagonal {
            let mut seen: Vec<(ExprId, ExprId)> = Vec::new();
            for (k, row) in t.iter().enumerate() {
                let e = row[k];
                let named = match seen.iter().find(|(d, _)| *d == e) {
                    Some(&(_, n)) => n,
                    None => namer.name(arena, e, &format!("I_{}", k + 1)),
                };
                seen.push((e, named));
                scene.inertia[k][k] = named;
            }
        } else {
            const AXES: [&str; 3] = ["x", "y", "z"];
            for i in 0..3 {
                for j in i..3 {
                    let n = namer.name(arena, t[i][j], &format!("I_{}{}", AXES[i], AXES[j]));
                    scene.inertia[i][j] = n;
                    scene.inertia[j][i] = n;
                }
            }
        }
        scene.mass = namer.name(arena, self.mass, "M");
        let on_axis = self.center[..2]
            .iter()
            .all(|&e| arena.as_rational(e).is_some_and(|r| r.is_zero()));
        if on_axis {
            scene.center[2] = namer.name(arena, self.center[2], "l");
        } else {
            for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                scene.center[k] = namer.name(arena, self.center[k], &format!("c_{axis}"));
            }
        }
        scene.gravity = self.gravity.map(|g| namer.name(arena, g, "g"));
        let mut values = namer.values;
        values.sort_by(|a, b| a.0.cmp(&b.0));
        (scene, values)
    }

    /// The paper-form printer of this scene: a user torque's inputs show as τ₁, τ₂, τ₃ (its
    /// components in body axes) whatever the caller named them, primed (τ′₁) if a symbol
    /// of the arena already prints so.
    fn paper<'a>(&self, arena: &'a Arena) -> Paper<'a> {
        let mut paper = Paper::new(arena);
        let taken = |latex: &str| arena.symbols().any(|(_, s)| s.latex == latex);
        let mut head = "\\tau".to_owned();
        while (1..=3).any(|k| taken(&format!("{head}_{{{k}}}"))) {
            head.push('\'');
        }
        for (k, &u) in self.user_torque.iter().flatten().enumerate() {
            if let Some(s) = arena.as_symbol(u) {
                paper = paper.rename(s, format!("{head}_{{{}}}", k + 1));
            }
        }
        paper
    }

    /// The operation counts of the methods `#[top]` generates, lowered from the same
    /// expressions the macro lowers.
    fn costs(
        &self,
        arena: &mut Arena,
        top: &TopDerivation,
        attitude: &Mat3,
        omega: &[ExprId; 3],
    ) -> Result<Vec<MethodCost>, LagrangeError> {
        let energy = top.energy(arena);
        let jacobian = top.jacobian(arena);
        let conserved: Vec<ExprId> = top.conserved_momenta.iter().flatten().copied().collect();
        let eulerian = self.eulerian_rhs(arena, attitude, omega)?;
        let programs: [(&'static str, &[ExprId]); 7] = [
            ("accelerations", &top.accelerations.accel),
            ("angle_jacobian", jacobian.as_flattened()),
            ("energy", &[energy]),
            ("conserved_momenta", &conserved),
            ("rotation_in", top.rotation.as_flattened()),
            ("rate_matrix_in", top.rate_matrix.as_flattened()),
            ("eulerian_rhs", &eulerian),
        ];
        Ok(programs
            .into_iter()
            .map(|(method, outputs)| MethodCost {
                method: Cow::Borrowed(method),
                ops: Program::lower(arena, outputs).op_count(),
            })
            .collect())
    }
}

/// Significant digits of the values in the definitions (the exact ones are in
/// [`Typeset::values`]).
const VALUE_DIGITS: usize = 6;

/// Gives names to the constants of a scene.
struct Namer {
    /// Every mass property is a constant: name them all.
    literal: bool,
    /// The LaTeX and value of each name given.
    values: Vec<(String, f64)>,
}

impl Namer {
    /// `e` itself unless it is a constant to name; then a fresh parameter called `name`
    /// (primed while a symbol has the name or its LaTeX).
    fn name(&mut self, arena: &mut Arena, e: ExprId, name: &str) -> ExprId {
        if !arena.free_symbols(e).is_empty() {
            return e;
        }
        let long = match arena.as_rational(e) {
            Some(r) if r.is_zero() => return e,
            Some(r) => !matches!(r.fraction(), Some((n, d)) if n.abs() < 1000 && d < 1000),
            None => true,
        };
        if !self.literal && !long {
            return e;
        }
        // Equal constants keep their own names (M = l = 1 is a coincidence of values);
        // only equal moments share one, which `TopScene::named` decides.
        let mut n = name.to_owned();
        while arena.symbols().any(|(_, s)| s.name == n) {
            n.push('\'');
        }
        let value = arena.eval(e, &[]);
        let p = arena.parameter(&n);
        let latex = arena
            .as_symbol(p)
            .map_or_else(|| n.clone(), |s| arena.symbol(s).latex.clone());
        self.values.push((latex, value));
        p
    }
}

fn owned(lines: Vec<String>) -> Lines {
    lines.into_iter().map(Cow::Owned).collect()
}

/// The LaTeX name of a bare symbol (coordinates and their derivatives are).
fn latex_of(arena: &Arena, e: ExprId) -> String {
    match arena.as_symbol(e) {
        Some(s) => arena.symbol(s).latex.clone(),
        None => crate::codegen::latex(arena, e),
    }
}

/// `name = definition` for every abbreviation the derivation's lines name, and those their
/// definitions name in turn, in order of name.
fn definitions(arena: &Arena, paper: &Paper<'_>, top: &TopDerivation) -> Vec<String> {
    let mut queue: Vec<ExprId> = vec![top.kinetic, top.gyrostatic, top.potential];
    queue.extend(top.forces.iter().copied());
    let mut found: Vec<SymbolId> = Vec::new();
    while let Some(e) = queue.pop() {
        for s in arena.free_symbols(e) {
            if arena.symbol(s).kind == SymbolKind::Abbreviation && !found.contains(&s) {
                found.push(s);
                queue.extend(arena.definition(s));
            }
        }
    }
    let mut lines: Vec<(String, String)> = found
        .into_iter()
        .filter_map(|s| {
            let d = arena.definition(s)?;
            let symbol = arena.symbol(s);
            Some((
                symbol.name.clone(),
                format!("{} = {}", symbol.latex, paper.latex(d)),
            ))
        })
        .collect();
    lines.sort();
    lines.into_iter().map(|(_, l)| l).collect()
}
