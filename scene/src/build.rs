//! Building a [`World`] from a [`Scene`].
//!
//! Each decimal literal is converted to the scalar once; all layout
//! arithmetic (pyramid offsets, grid positions) is then done in the scalar,
//! so the built world is the same on every machine.

use super::{
    Generator, MAX_SCENE_BODIES, Scene, SceneAnchor, SceneBody, SceneConstraint, SceneError,
    SceneKind, SceneMaterial, SceneShape,
};
use clockwork2d::constraints::{Anchor, Constraint};
use clockwork2d::dynamics::{BodyDef, BodyId};
use clockwork2d::geometry::Shape;
use clockwork2d::math::{Scalar, Vec2};
use clockwork2d::world::{World, WorldSettings};

/// Converts a literal, refusing NaN and infinities.
fn num<S: Scalar>(value: f64, what: &dyn Fn() -> String) -> Result<S, SceneError> {
    if value.is_finite() {
        Ok(S::from_f64(value))
    } else {
        Err(SceneError::NotFinite { what: what() })
    }
}

fn pair<S: Scalar>(value: (f64, f64), what: &dyn Fn() -> String) -> Result<Vec2<S>, SceneError> {
    Ok(Vec2::new(num(value.0, what)?, num(value.1, what)?))
}

fn shape<S: Scalar>(s: &SceneShape, what: &dyn Fn() -> String) -> Result<Shape<S>, SceneError> {
    Ok(match *s {
        SceneShape::Circle { radius } => Shape::circle(num(radius, what)?),
        SceneShape::Box { half } => Shape::aabb(pair(half, what)?),
    })
}

fn def<S: Scalar>(
    kind: SceneKind,
    shape: Shape<S>,
    material: &SceneMaterial,
    what: &dyn Fn() -> String,
) -> Result<BodyDef<S>, SceneError> {
    let base = match kind {
        SceneKind::Fixed => BodyDef::fixed(shape),
        SceneKind::Kinematic => BodyDef::kinematic(shape),
        SceneKind::Dynamic => BodyDef::dynamic(shape),
    };
    Ok(base
        .density(num(material.density, what)?)
        .restitution(num(material.restitution, what)?)
        .friction(num(material.friction, what)?)
        .gravity_scale(num(material.gravity_scale, what)?)
        .bullet(material.bullet))
}

/// SplitMix64: a tiny, well-known integer generator (no floats).
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A value in [-1, 1] in steps of 1/1024, from the generator.
fn unit_step<S: Scalar>(state: &mut u64) -> S {
    let k = i32::try_from(splitmix(state) % 2049).unwrap_or(0) - 1024;
    S::from_ratio(k, 1024)
}

impl Generator {
    /// Number of bodies the generator creates (saturating).
    #[must_use]
    pub fn body_count(&self) -> u64 {
        match *self {
            Generator::Stack { count, .. } => u64::from(count),
            Generator::Pyramid { rows, .. } => {
                let r = u64::from(rows);
                r.saturating_mul(r.saturating_add(1)) / 2
            }
            Generator::Grid { columns, rows, .. } => {
                u64::from(columns).saturating_mul(u64::from(rows))
            }
            Generator::Walls { .. } => 4,
            Generator::Chain { segments, .. } => u64::from(segments),
        }
    }
}

impl Scene {
    /// Number of bodies the scene creates (saturating).
    #[must_use]
    pub fn body_count(&self) -> u64 {
        self.generators
            .iter()
            .fold(self.bodies.len() as u64, |n, g| {
                n.saturating_add(g.body_count())
            })
    }

    /// The world settings the scene asks for.
    ///
    /// # Errors
    /// [`SceneError`] for a non-finite number or an out-of-range setting.
    pub fn world_settings<S: Scalar>(&self) -> Result<WorldSettings<S>, SceneError> {
        let what = || "settings".to_owned();
        let o = &self.settings;
        let mut s = WorldSettings::<S>::default();
        if let Some(g) = o.gravity {
            s.gravity = pair(g, &what)?;
        }
        if let Some(dt) = o.dt {
            s.dt = num(dt, &what)?;
        }
        if let Some(v) = o.velocity_iterations {
            s.velocity_iterations = v;
        }
        if let Some(v) = o.position_iterations {
            s.position_iterations = v;
        }
        if let Some(v) = o.substeps {
            s.substeps = v;
        }
        if let Some(v) = o.sleep_enabled {
            s.sleep_enabled = v;
        }
        if let Some(b) = o.bounds {
            s.bounds.half_extents = pair(b, &what)?;
        }
        s.validate().map_err(|error| SceneError::World {
            what: "settings".to_owned(),
            error,
        })?;
        Ok(s)
    }

    /// Builds the world the scene describes.
    ///
    /// # Errors
    /// [`SceneError`] naming the body or setting that was refused.
    pub fn build<S: Scalar>(&self) -> Result<World<S>, SceneError> {
        let total = self.body_count();
        if total > MAX_SCENE_BODIES {
            return Err(SceneError::TooManyBodies(total));
        }
        let mut world =
            World::try_new(self.world_settings::<S>()?).map_err(|error| SceneError::World {
                what: "settings".to_owned(),
                error,
            })?;
        let mut ids = Vec::new();
        for (i, body) in self.bodies.iter().enumerate() {
            let what = || format!("body {i}");
            ids.push(add_scene_body(&mut world, body, &what)?);
        }
        for (g, generator) in self.generators.iter().enumerate() {
            let what = || format!("generator {g}");
            let first = ids.len();
            for def in generator.defs::<S>(&what)? {
                ids.push(world.add_body(def).map_err(|error| SceneError::World {
                    what: what(),
                    error,
                })?);
            }
            if let Generator::Chain {
                pivot,
                segment_length,
                ..
            } = *generator
            {
                let length: S = num(segment_length, &what)?;
                let mut previous = Anchor::Point(pair(pivot, &what)?);
                for &id in &ids[first..] {
                    world
                        .add_constraint(Constraint::rope(previous, Anchor::Body(id), length))
                        .map_err(|error| SceneError::World {
                            what: what(),
                            error,
                        })?;
                    previous = Anchor::Body(id);
                }
            }
        }
        for (c, constraint) in self.constraints.iter().enumerate() {
            let what = || format!("constraint {c}");
            let built = scene_constraint::<S>(constraint, &ids, &what)?;
            world
                .add_constraint(built)
                .map_err(|error| SceneError::World {
                    what: what(),
                    error,
                })?;
        }
        Ok(world)
    }
}

fn add_scene_body<S: Scalar>(
    world: &mut World<S>,
    body: &SceneBody,
    what: &dyn Fn() -> String,
) -> Result<BodyId, SceneError> {
    let d = def(body.kind, shape(&body.shape, what)?, &body.material, what)?
        .position(pair(body.position, what)?)
        .velocity(pair(body.velocity, what)?);
    world.add_body(d).map_err(|error| SceneError::World {
        what: what(),
        error,
    })
}

fn anchor<S: Scalar>(
    a: &SceneAnchor,
    ids: &[BodyId],
    what: &dyn Fn() -> String,
) -> Result<Anchor<S>, SceneError> {
    let body = |i: u32| {
        ids.get(i as usize)
            .copied()
            .ok_or_else(|| SceneError::BadReference {
                what: what(),
                index: i,
                bodies: ids.len(),
            })
    };
    Ok(match *a {
        SceneAnchor::Point(p) => Anchor::Point(pair(p, what)?),
        SceneAnchor::Body(i) => Anchor::Body(body(i)?),
        SceneAnchor::BodyOffset(i, offset) => Anchor::BodyOffset(body(i)?, pair(offset, what)?),
    })
}

fn scene_constraint<S: Scalar>(
    c: &SceneConstraint,
    ids: &[BodyId],
    what: &dyn Fn() -> String,
) -> Result<Constraint<S>, SceneError> {
    Ok(match *c {
        SceneConstraint::BendySpring {
            a,
            b,
            stiffness,
            damping,
            rest_offset,
        } => Constraint::bendy_spring(
            anchor(&a, ids, what)?,
            anchor(&b, ids, what)?,
            pair(stiffness, what)?,
            num(damping, what)?,
        )
        .with_rest_offset(pair(rest_offset, what)?),
        SceneConstraint::RadialSpring {
            pivot,
            body,
            rest_length,
            stiffness,
            damping,
        } => Constraint::radial_spring(
            anchor(&pivot, ids, what)?,
            anchor(&body, ids, what)?,
            num(rest_length, what)?,
            num(stiffness, what)?,
            num(damping, what)?,
        ),
        SceneConstraint::Rope {
            a,
            b,
            length,
            restitution,
        } => Constraint::rope(
            anchor(&a, ids, what)?,
            anchor(&b, ids, what)?,
            num(length, what)?,
        )
        .with_restitution(num(restitution, what)?),
    })
}

impl Generator {
    /// The body definitions, in creation order.
    fn defs<S: Scalar>(&self, what: &dyn Fn() -> String) -> Result<Vec<BodyDef<S>>, SceneError> {
        let mut out = Vec::new();
        match *self {
            Generator::Stack {
                count,
                half,
                base,
                gap,
                material,
            } => {
                let half: Vec2<S> = pair(half, what)?;
                let base: Vec2<S> = pair(base, what)?;
                let gap: S = num(gap, what)?;
                let pitch = half.y.mul_int(2).add(gap);
                for i in 0..count {
                    let k = i32::try_from(i).unwrap_or(i32::MAX);
                    let y = base.y.add(half.y).add(pitch.mul_int(k));
                    out.push(
                        def(SceneKind::Dynamic, Shape::aabb(half), &material, what)?
                            .position(Vec2::new(base.x, y)),
                    );
                }
            }
            Generator::Pyramid {
                rows,
                half,
                spacing,
                base,
                material,
            } => {
                let half: Vec2<S> = pair(half, what)?;
                let base: Vec2<S> = pair(base, what)?;
                let spacing: S = num(spacing, what)?;
                let height = half.y.mul_int(2);
                let rows_i = i32::try_from(rows).unwrap_or(i32::MAX);
                for r in 0..rows_i {
                    let n = rows_i - r;
                    // Centre of box i in a row of n: (i - (n-1)/2)·spacing,
                    // computed as (2i - (n-1))·spacing/2 to stay exact.
                    for i in 0..n {
                        let x = base.x.add(spacing.mul_int(2 * i - (n - 1)).half());
                        let y = base.y.add(half.y).add(height.mul_int(r));
                        out.push(
                            def(SceneKind::Dynamic, Shape::aabb(half), &material, what)?
                                .position(Vec2::new(x, y)),
                        );
                    }
                }
            }
            Generator::Grid {
                columns,
                rows,
                shape: s,
                origin,
                spacing,
                speed,
                seed,
                material,
            } => {
                let shape_s = shape::<S>(&s, what)?;
                let origin: Vec2<S> = pair(origin, what)?;
                let spacing: Vec2<S> = pair(spacing, what)?;
                let speed: S = num(speed, what)?;
                let mut state = seed;
                for r in 0..i32::try_from(rows).unwrap_or(i32::MAX) {
                    for c in 0..i32::try_from(columns).unwrap_or(i32::MAX) {
                        let position = Vec2::new(
                            origin.x.add(spacing.x.mul_int(c)),
                            origin.y.add(spacing.y.mul_int(r)),
                        );
                        let velocity = if speed == S::ZERO {
                            Vec2::ZERO
                        } else {
                            let vx = unit_step::<S>(&mut state).mul(speed);
                            let vy = unit_step::<S>(&mut state).mul(speed);
                            Vec2::new(vx, vy)
                        };
                        out.push(
                            def(SceneKind::Dynamic, shape_s, &material, what)?
                                .position(position)
                                .velocity(velocity),
                        );
                    }
                }
            }
            Generator::Chain {
                pivot,
                direction,
                segments,
                segment_length,
                link_radius,
                material,
            } => {
                let pivot: Vec2<S> = pair(pivot, what)?;
                let direction = pair::<S>(direction, what)?.try_normalize().ok_or_else(|| {
                    SceneError::Invalid {
                        what: what(),
                        reason: "chain direction must not be zero",
                    }
                })?;
                let length: S = num(segment_length, what)?;
                let radius: S = num(link_radius, what)?;
                for i in 1..=i32::try_from(segments).unwrap_or(i32::MAX) {
                    let position = pivot + direction.scale(length.mul_int(i));
                    out.push(
                        def(SceneKind::Dynamic, Shape::circle(radius), &material, what)?
                            .position(position),
                    );
                }
            }
            Generator::Walls {
                kind,
                center,
                half,
                thickness,
            } => {
                let c: Vec2<S> = pair(center, what)?;
                let h: Vec2<S> = pair(half, what)?;
                let t: S = num(thickness, what)?;
                let ht = t.half();
                let m = SceneMaterial::default();
                // Floor and ceiling span the full outer width.
                let wide = Vec2::new(h.x.add(t), ht);
                let tall = Vec2::new(ht, h.y);
                for (offset, half_extents) in [
                    (Vec2::new(S::ZERO, h.y.add(ht).neg()), wide),
                    (Vec2::new(S::ZERO, h.y.add(ht)), wide),
                    (Vec2::new(h.x.add(ht).neg(), S::ZERO), tall),
                    (Vec2::new(h.x.add(ht), S::ZERO), tall),
                ] {
                    out.push(def(kind, Shape::aabb(half_extents), &m, what)?.position(c + offset));
                }
            }
        }
        Ok(out)
    }
}
