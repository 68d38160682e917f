//! Phase "punched motion": the motion the velocity solve adds to a body
//! beyond what its contacts were looked for with is stopped at the
//! immovable bodies (fixed, kinematic, asleep) it would pass.
//!
//! Why: the broad phase pairs a body within its swept box (its motion at
//! the velocity before the solve, plus the speculative margin on every
//! side), and the narrow phase keeps a pair's row only when the pair can
//! close to the margin at that velocity (`s ≤ margin + max(0, −v_n)·h`).
//! The solve can change a body's velocity by far more: a light body wedged
//! between heavy ones (1000×) under g = 100 left the solve at 400 units/s,
//! moved 6 units in one tick through a wall it had no row with (and no
//! pair), and flew to the world's bound. Bullets too: [`World::integrate`]
//! cuts a bullet at its time of impact against its broad-phase partners
//! only, and a bullet at rest struck by a faster body (its proxy its box
//! grown by the margin) left the solve at 25 units/s through a wall 0.3
//! away that it was never paired with.
//!
//! Which bodies: a body whose displacement changed in the solve by at most
//! `margin/8` per axis (under `margin/5` in length) stays clear of every
//! pair it has no row with, even after the position pass's correction (at
//! most `margin/2` per axis, [`World::bound_corrections`]): `0.18 + 0.71 <
//! 1` margin. Any other body is "punched", and
//!
//! 1. if its box swept by the new displacement, grown by `margin/2` (the
//!    correction's bound), leaves its proxy, the immovable bodies in that
//!    grown region are found (a second broad-phase query over the punched
//!    bodies' grown regions and the immovable proxies only): bodies beyond
//!    the proxy were never paired with it;
//! 2. against each immovable body it is paired with (by the broad phase or
//!    by step 1) but has no contact row with, its displacement is stopped
//!    along the normal at the earliest time of impact (it slides on along
//!    the obstacle), and its approach velocity along that normal is taken
//!    out (an inelastic impact: a velocity it never moves by would push it
//!    into the obstacle again next substep).
//!
//! 3. the bodies following a body cut in step 2 along their rows are held
//!    behind it ([`super::punched_followers`]): their displacements are
//!    shortened along their own paths.
//!
//! A punched body's motion is otherwise left as the solve made it: its rows
//! with other moving bodies assume both move by `v·h` (a bullet's row with
//! a free box it punched held the bullet in front of the box only because
//! the box moved as fast as the bullet; shortening the box's motion put the
//! bullet half through it). Step 2 runs again after the position pass and
//! the projection out of immovable bodies (which projects along rows only:
//! a crowd pushed a punched body 0.05, the correction's bound, into a wall
//! it had just been stopped at).

use crate::collision::{ProxyClass, shape_toi};
use crate::geometry::Toi;
use crate::math::Scalar;
use crate::solver::StepContext;
use crate::world::World;

use super::punched_followers::hold_followers_behind;

impl<S: Scalar> World<S> {
    /// Keeps the velocities the narrow phase saw, for
    /// [`World::cut_punched_motion`].
    pub(super) fn remember_predicted_velocities(&mut self) {
        let context = &mut self.step_context;
        context.predicted_velocities.clone_from(&context.velocities);
    }

    /// Finds the punched bodies and the immovable bodies beyond their
    /// proxies (steps 1 and 2 of the [module docs](self)), then cuts their
    /// motion at the immovable bodies they have no row with.
    pub(super) fn cut_punched_motion(&mut self, h: S) {
        let margin = self.settings.speculative_margin;
        let threshold = margin.mul(S::from_ratio(1, 8));
        let grow = margin.half();
        let context = &mut self.step_context;
        for &i in &context.punched {
            context.punched_mark[i as usize] = false;
        }
        context.punched.clear();
        context.escape_pairs.clear();
        context.punched_obstacles.clear();
        context.punched_mark.resize(self.slots.len(), false);
        // |Δv| > (margin/8)/h on an axis: the displacement changed by more
        // than margin/8 on it (velocities first: most bodies are not).
        let limit = threshold.div(h);
        for (i, (v, predicted)) in context
            .velocities
            .iter()
            .zip(&context.predicted_velocities)
            .enumerate()
        {
            let change = *v - *predicted;
            if change.x.abs() <= limit && change.y.abs() <= limit {
                continue;
            }
            let Some(body) = self.slots.get(i).and_then(|slot| slot.body.as_ref()) else {
                continue;
            };
            if !body.is_simulated_dynamic() {
                continue;
            }
            context.punched.push(u32::try_from(i).unwrap_or(u32::MAX));
            context.punched_mark[i] = true;
        }
        if context.punched.is_empty() {
            return;
        }
        // Step 1: the punched bodies whose grown swept box leaves their
        // proxy take part with that region (joined with the proxy) in a
        // query against the immovable proxies; every other awake dynamic
        // body stays out of it.
        context.escape_proxies.clear();
        let mut any_escapes = false;
        for proxy in &context.proxies {
            match proxy.class {
                Some(ProxyClass::Dynamic) => {}
                Some(_) => {
                    context.escape_proxies.push(*proxy);
                    continue;
                }
                None => continue,
            }
            if !context.punched_mark[proxy.index as usize] {
                continue;
            }
            let i = proxy.index as usize;
            let Some(body) = self.slots[i].body.as_ref() else {
                continue;
            };
            let now = body.aabb();
            let later = body
                .shape
                .bounding_aabb_at(body.position + context.displacements[i]);
            let reach = now.union(&later).expanded(grow);
            let (lo, hi) = (reach.min(), reach.max());
            if proxy.covers(lo, hi) {
                continue;
            }
            any_escapes = true;
            context.escape_proxies.push(proxy.escaping_over(lo, hi));
        }
        if any_escapes {
            context
                .escape_broad_phase
                .find_pairs(&context.escape_proxies, &mut context.escape_pairs);
            // Keep (punched, immovable) pairs the main broad phase did not
            // already find (a sleeping body and a moving kinematic one also
            // pair there; neither is punched).
            let pairs = &context.pairs;
            context
                .escape_pairs
                .retain(|pair| pairs.binary_search(pair).is_err());
        }
        // The (punched, immovable) pairs of both lists, then those with a
        // contact row left out: the row's speculative target stops the body
        // at the contact, and a bounce is timed from it.
        let StepContext {
            pairs,
            escape_pairs,
            inverse_masses,
            punched_mark,
            punched_obstacles,
            constraints,
            ..
        } = context;
        for &(a, b) in pairs.iter().chain(escape_pairs.iter()) {
            if !(punched_mark[a as usize] || punched_mark[b as usize]) {
                continue;
            }
            for (mover, other) in [(a, b), (b, a)] {
                if punched_mark[mover as usize] && !inverse_masses[other as usize].is_positive() {
                    punched_obstacles.push((mover, other));
                }
            }
        }
        if punched_obstacles.is_empty() {
            return;
        }
        punched_obstacles.sort_unstable();
        let mut with_row = false;
        for c in constraints.iter() {
            if c.inverse_mass_a.is_positive() == c.inverse_mass_b.is_positive() {
                continue;
            }
            for key in [(c.a, c.b), (c.b, c.a)] {
                if let Ok(k) = punched_obstacles.binary_search(&key) {
                    punched_obstacles[k].1 = u32::MAX;
                    with_row = true;
                }
            }
        }
        if with_row {
            punched_obstacles.retain(|&(_, other)| other != u32::MAX);
        }
        if self.cut_punched_at_immovable_partners(true) {
            let context = &mut self.step_context;
            hold_followers_behind(
                &context.constraints,
                &mut context.hold_links,
                &mut context.displacements,
                &context.uncut_displacements,
                &mut context.hold_rank,
            );
        }
    }

    /// Step 2 of the [module docs](self): each punched body's displacement
    /// is stopped along the normal at its earliest time of impact against
    /// the immovable bodies it is paired with (this substep's pairs and
    /// those step 1 found) but has no row with, and its approach along that
    /// normal is taken out. Called from [`World::cut_punched_motion`] and
    /// again after [`World::project_out_of_immovable`]. With `rank` (the
    /// first call), the displacements before the first cut are kept and
    /// each cut body is ranked 1 for [`hold_followers_behind`]; returns
    /// whether any body was cut then.
    pub(super) fn cut_punched_at_immovable_partners(&mut self, rank: bool) -> bool {
        let half_slop = self.settings.linear_slop.half();
        let context = &mut self.step_context;
        let mut any_cut = false;
        for &(mover, other) in &context.punched_obstacles {
            let (Some(mb), Some(ob)) = (
                self.slots[mover as usize].body.as_ref(),
                self.slots[other as usize].body.as_ref(),
            ) else {
                continue;
            };
            let full = context.displacements[mover as usize];
            if let Toi::Hit { t, normal } = shape_toi(
                &mb.shape,
                mb.position,
                full,
                &ob.shape,
                ob.position,
                context.displacements[other as usize],
            ) {
                // Only the motion into the obstacle after the contact
                // is cut (the body slides on along it): cutting the
                // whole displacement stopped a body sliding down a wall
                // it grazed, leaving it a velocity it never moved by.
                let into = full.dot(normal);
                let past = if into.is_positive() {
                    into.sub(into.mul(t))
                } else {
                    S::ZERO
                };
                // A body that would end at most half the slop past the
                // obstacle ends where a resting contact may (depth below
                // the slop): it is left as the solve made it, and the
                // next substep's narrow phase gives the pair a row
                // (touching is within the margin), from which a bounce
                // is timed. Stopping it there took out the speculative
                // approach a row with a flush neighbour tile had allowed
                // (the body reaches the contact at t = 1), and a ball
                // landing on tiles lost most of its bounce.
                if past <= half_slop {
                    continue;
                }
                if rank {
                    if !any_cut {
                        // The displacements before the first cut: the
                        // hold measures its rows against them.
                        context
                            .uncut_displacements
                            .clone_from(&context.displacements);
                        context.hold_rank.clear();
                        context.hold_rank.resize(context.displacements.len(), 0);
                    }
                    context.hold_rank[mover as usize] = 1;
                    any_cut = true;
                }
                context.displacements[mover as usize] = full - normal.scale(past);
                // The impact is inelastic: the approach along the
                // normal (from the mover to the obstacle) is taken
                // out.
                let (m, o) = (mover as usize, other as usize);
                let vn = (context.velocities[o] - context.velocities[m]).dot(normal);
                if vn.is_negative() {
                    context.velocities[m] += normal.scale(vn);
                }
            }
        }
        any_cut
    }
}
