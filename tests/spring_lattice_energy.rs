//! Spring lattices keep their energy (issue 13): 32 × 32 lattices of light
//! bodies (density 1) joined to their neighbours by springs, gravity off,
//! damping 0, one corner kicked, 60 s at the default step (dt = 1/60,
//! substeps 1).
//!
//! The physics: with no damping, no gravity and no contacts, the lattice
//! is a closed Hamiltonian system, so its total energy (kinetic + spring)
//! is constant. The engine's θ-method (module docs of
//! `clockwork2d::constraints`) solves all springs together, so on the
//! (linearised) lattice it can only lose energy: per step
//! `ΔE = −Σ_b (θ_b − ½)·m_b·|Δv_b|² − Σ_s (θ_s − ½)·k_s·Δx_s² ≤ 0`.
//! Bounds checked here, from the issue:
//!
//! * the energy never exceeds 1.01 × its start, at any ω·h;
//! * where ω·h ≤ 0.3 it never falls more than 1 % below its start. The
//!   blend there is `θ − ½ = (ω·h)⁸/512`, and a mode of frequency Ω loses
//!   `2·(θ − ½)·(Ω·h)²` of its energy per step; a body with four springs
//!   has (Ω·h)² ≤ 4·(ω·h)² (Gershgorin), so over 3600 steps at ω·h = 0.3
//!   the loss is at most 3600 · 2 · 1.3e-7 · 0.36 = 3.3e-4.
//!
//! `ω² = k·(w_a + w_b)` per spring, as `clockwork2d::constraints` defines
//! it; for two equal bodies of mass m, `k = (ω·h)²·m / (2·h²)`.
//!
//! Energy is computed in f64 from the engine's state (positions,
//! velocities, masses) and the springs' own parameters: this test's own
//! physics, not the engine's internals. Figures are printed with
//! `--nocapture`:
//! `cargo test --release --test spring_lattice_energy -- --nocapture`.
//!
//! The full 60-second runs of the issue's four cases run in every profile;
//! the adversarial variants (more stiffnesses, uneven masses, an anchored
//! edge, radial lattices, a chain) run their full 60 s in release (CI runs
//! `cargo test --release`) and 10 s in debug, where the test profile is
//! slow.

use clockwork2d::prelude::*;

/// The engine's tick, 1/60 s.
const H: f64 = 1.0 / 60.0;
/// 60 s at 60 Hz: the issue's run length.
const FULL_TICKS: usize = 3600;
/// The adversarial variants' run length in this profile.
const VARIANT_TICKS: usize = if cfg!(debug_assertions) { 600 } else { 3600 };
/// Lattice spacing and body radius: neighbours are 1.0 apart, the circles
/// 0.4 across, so a gap of 0.6 that the small oscillations here (well
/// under 0.2) never close: no contacts.
const SPACING: f64 = 1.0;
const RADIUS: f64 = 0.2;

/// What kind of spring joins two neighbours.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A bendy spring (one spring per axis, both stiffness k) toward the
    /// neighbour plus the rest offset.
    Bendy,
    /// A radial spring along the line between the two, rest length the
    /// spacing.
    Radial,
}

/// One end of a spring as the test sees it.
#[derive(Clone, Copy)]
enum End {
    Body(usize),
    Point((f64, f64)),
}

struct Spring {
    a: End,
    b: End,
    k: f64,
    rest: (f64, f64),
}

struct Lattice {
    world: World,
    bodies: Vec<BodyId>,
    masses: Vec<f64>,
    springs: Vec<Spring>,
    kind: Kind,
}

impl Lattice {
    fn position(&self, end: End) -> (f64, f64) {
        match end {
            End::Body(i) => self
                .world
                .body(self.bodies[i])
                .expect("body")
                .position()
                .to_f64(),
            End::Point(p) => p,
        }
    }

    /// Kinetic + spring energy in f64 from the state.
    #[allow(clippy::float_arithmetic)]
    fn energy(&self) -> f64 {
        let mut e = 0.0;
        for (id, m) in self.bodies.iter().zip(&self.masses) {
            let (vx, vy) = self.world.body(*id).expect("body").velocity().to_f64();
            e += 0.5 * m * (vx * vx + vy * vy);
        }
        for s in &self.springs {
            let (pa, pb) = (self.position(s.a), self.position(s.b));
            let d = (pb.0 - pa.0, pb.1 - pa.1);
            e += match self.kind {
                Kind::Bendy => {
                    let (sx, sy) = (d.0 - s.rest.0, d.1 - s.rest.1);
                    0.5 * s.k * (sx * sx + sy * sy)
                }
                Kind::Radial => {
                    let stretch = d.0.hypot(d.1) - s.rest.0.hypot(s.rest.1);
                    0.5 * s.k * stretch * stretch
                }
            };
        }
        e
    }
}

/// How the lattice is built.
#[derive(Clone, Copy)]
struct Spec {
    columns: usize,
    rows: usize,
    kind: Kind,
    /// ω·h of a spring between two bodies of the lightest mass.
    omega_h: f64,
    /// Every third body (in a pattern that is not a lattice direction) is
    /// this many times denser.
    heavy_ratio: f64,
    /// The top row also hangs from fixed points one spacing above it.
    anchored_top: bool,
}

impl Spec {
    fn lattice(columns: usize, rows: usize, kind: Kind, omega_h: f64) -> Self {
        Spec {
            columns,
            rows,
            kind,
            omega_h,
            heavy_ratio: 1.0,
            anchored_top: false,
        }
    }
}

#[allow(clippy::float_arithmetic)]
fn build(spec: Spec) -> Lattice {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, 0.0),
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let mut bodies = Vec::new();
    let mut masses = Vec::new();
    for r in 0..spec.rows {
        for c in 0..spec.columns {
            let heavy = (r + 2 * c) % 3 == 0;
            let density = if heavy { spec.heavy_ratio } else { 1.0 };
            // The corner body (0, 0) is kicked.
            let velocity = if r == 0 && c == 0 {
                (1.0, 0.5)
            } else {
                (0.0, 0.0)
            };
            let id = world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(RADIUS)))
                        .density(fx(density))
                        .position(vec2(c as f64 * SPACING, r as f64 * SPACING))
                        .velocity(vec2(velocity.0, velocity.1)),
                )
                .expect("lattice body");
            masses.push(world.body(id).expect("body").mass().to_f64());
            bodies.push(id);
        }
    }
    // k from the lightest body's mass m: ω² = k·(2/m) at the target ω·h.
    let light = masses.iter().copied().fold(f64::INFINITY, f64::min);
    let omega = spec.omega_h / H;
    let k = omega * omega * light / 2.0;
    let mut springs = Vec::new();
    let index = |r: usize, c: usize| r * spec.columns + c;
    for r in 0..spec.rows {
        for c in 0..spec.columns {
            if c + 1 < spec.columns {
                springs.push((
                    End::Body(index(r, c)),
                    End::Body(index(r, c + 1)),
                    (SPACING, 0.0),
                ));
            }
            if r + 1 < spec.rows {
                springs.push((
                    End::Body(index(r, c)),
                    End::Body(index(r + 1, c)),
                    (0.0, SPACING),
                ));
            }
        }
    }
    if spec.anchored_top {
        let top = spec.rows - 1;
        for c in 0..spec.columns {
            let anchor = (c as f64 * SPACING, (top + 1) as f64 * SPACING);
            springs.push((End::Body(index(top, c)), End::Point(anchor), (0.0, SPACING)));
        }
    }
    let anchor = |end: End| match end {
        End::Body(i) => Anchor::Body(bodies[i]),
        End::Point(p) => Anchor::Point(vec2(p.0, p.1)),
    };
    let mut out = Vec::new();
    for (a, b, rest) in springs {
        let constraint = match spec.kind {
            Kind::Bendy => Constraint::bendy_spring(anchor(a), anchor(b), vec2(k, k), fx(0.0))
                .with_rest_offset(vec2(rest.0, rest.1)),
            Kind::Radial => Constraint::radial_spring(
                anchor(a),
                anchor(b),
                fx(rest.0.hypot(rest.1)),
                fx(k),
                fx(0.0),
            ),
        };
        world.add_constraint(constraint).expect("spring");
        out.push(Spring { a, b, k, rest });
    }
    Lattice {
        world,
        bodies,
        masses,
        springs: out,
        kind: spec.kind,
    }
}

/// Steps `ticks` ticks; returns (max, min) of E/E₀ over all ticks.
#[allow(clippy::float_arithmetic)]
fn energy_extremes(lattice: &mut Lattice, ticks: usize) -> (f64, f64) {
    let e0 = lattice.energy();
    assert!(e0 > 0.0);
    let (mut high, mut low) = (1.0f64, 1.0f64);
    for _ in 0..ticks {
        lattice.world.step();
        let ratio = lattice.energy() / e0;
        high = high.max(ratio);
        low = low.min(ratio);
    }
    (high, low)
}

/// Runs the cases, prints a table, and checks the issue's bounds.
#[allow(clippy::float_arithmetic)]
fn check(title: &str, cases: &[Spec], ticks: usize) {
    println!("{title}: {} s at dt = 1/60, substeps 1", ticks as f64 * H);
    println!("  kind    size    ω·h   mass ratio  anchored   max E/E₀   min E/E₀");
    let mut failures = Vec::new();
    for &spec in cases {
        let mut lattice = build(spec);
        let (high, low) = energy_extremes(&mut lattice, ticks);
        println!(
            "  {:<6} {:>2}×{:<3} {:>5}   {:>6}      {:<5}    {high:.6}   {low:.6}",
            format!("{:?}", spec.kind),
            spec.columns,
            spec.rows,
            spec.omega_h,
            spec.heavy_ratio,
            spec.anchored_top
        );
        if high > 1.01 {
            failures.push(format!("{spec:?}: energy rose to {high} × its start"));
        }
        if spec.omega_h <= 0.3 && low < 0.99 && !(spec.kind == Kind::Radial && spec.rows > 1) {
            failures.push(format!("{spec:?}: energy fell to {low} × its start"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

impl std::fmt::Debug for Spec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{:?} {}×{} ω·h={} mass ratio {} anchored {}",
            self.kind, self.columns, self.rows, self.omega_h, self.heavy_ratio, self.anchored_top
        )
    }
}

/// The issue's four cases: 32 × 32 bendy lattices at ω·h = 0.3, 1, 1.5 and
/// 3, full 60 s.
#[test]
fn bendy_lattice_32x32_issue_cases_never_gain_energy_over_60_s() {
    let cases: Vec<Spec> = [0.3, 1.0, 1.5, 3.0]
        .iter()
        .map(|&w| Spec::lattice(32, 32, Kind::Bendy, w))
        .collect();
    check("bendy 32×32 (issue 13)", &cases, FULL_TICKS);
}

/// The other stiffnesses: ω·h = 0.1 (resolved: the lower bound applies),
/// 2, 5 and 10 (far beyond what the step resolves).
#[test]
fn bendy_lattice_32x32_other_stiffnesses_never_gain_energy() {
    let cases: Vec<Spec> = [0.1, 2.0, 5.0, 10.0]
        .iter()
        .map(|&w| Spec::lattice(32, 32, Kind::Bendy, w))
        .collect();
    check("bendy 32×32, other ω·h", &cases, VARIANT_TICKS);
}

/// The other kind of lattice: radial springs (a spring along each pole).
/// Only the upper bound is checked: a square lattice of central springs
/// has no shear stiffness, its cells shear freely, and the engine
/// linearises each radial spring once per step along its pole, which
/// misses the second-order stretch `|Δr⊥|²/(2·|r|)` of that sideways
/// motion; over 60 s at ω·h = 0.3 the lattice loses 14 % of its energy
/// (printed; the chains below, which cannot shear, keep theirs to 1e-4).
#[test]
fn radial_lattice_32x32_never_gains_energy() {
    let cases: Vec<Spec> = [0.3, 1.0, 1.5, 3.0]
        .iter()
        .map(|&w| Spec::lattice(32, 32, Kind::Radial, w))
        .collect();
    check("radial 32×32", &cases, VARIANT_TICKS);
}

/// Uneven masses (every third body 10× or 100× denser) and a top edge
/// hanging from fixed points.
#[test]
fn uneven_and_anchored_lattices_never_gain_energy() {
    let mut cases = Vec::new();
    for &ratio in &[10.0, 100.0] {
        for &w in &[0.3, 1.0, 3.0] {
            cases.push(Spec {
                heavy_ratio: ratio,
                ..Spec::lattice(32, 32, Kind::Bendy, w)
            });
        }
    }
    for &w in &[0.3, 1.5] {
        cases.push(Spec {
            anchored_top: true,
            ..Spec::lattice(32, 32, Kind::Bendy, w)
        });
    }
    check("uneven masses, anchored edge", &cases, VARIANT_TICKS);
}

/// A 1 × 200 chain of springs (the slowest-converging shape for an
/// iterative solve: its lowest mode is (200/π)² below its highest).
#[test]
fn spring_chain_1x200_never_gains_energy() {
    let mut cases = Vec::new();
    for &kind in &[Kind::Bendy, Kind::Radial] {
        for &w in &[0.1, 0.3, 1.0, 1.5, 3.0, 10.0] {
            cases.push(Spec::lattice(200, 1, kind, w));
        }
    }
    check("chain 200×1", &cases, VARIANT_TICKS);
}
