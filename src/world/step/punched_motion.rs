//! Phase "punched motion": the motion the velocity solve adds to a body
//! beyond what its contacts were looked for with is stopped at the bodies
//! it would pass and has no row with.
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
//!    correction's bound), leaves its proxy, the bodies in that grown
//!    region are found (a second broad-phase query of the punched bodies'
//!    grown regions against every other proxy): bodies beyond the proxy
//!    were never paired with it;
//! 2. against each immovable body (fixed, kinematic, asleep) it is paired
//!    with (by the broad phase or by step 1) but has no contact row with,
//!    its displacement is stopped along the normal at the earliest time of
//!    impact (it slides on along the obstacle), and its approach velocity
//!    along that normal is taken out (an inelastic impact: a velocity it
//!    never moves by would push it into the obstacle again next substep);
//! 3. with each movable body it is paired with but has no row with, the
//!    two sweeps (both displacements) are timed: when they meet at `t` and
//!    their motion into each other after it passes half the slop, each of
//!    the two whose motion goes into the other is stopped at the meeting,
//!    its displacement scaled by `t`, unless a spring pulls it (held back
//!    with its velocity kept, it would stretch its springs). A ball at 50 units/s behind a box 100×
//!    lighter that had bounced off a wall 2 away still closed on the box,
//!    which kept 51.9 units/s towards the wall at the narrow phase (the pair
//!    predicted separating: no row); the box's row with the wall stopped it
//!    and the ball flew 0.196 into it. And a punched box of a row driven
//!    into a wall flew into the next box, which its proxy (at rest) did not
//!    reach;
//! 4. the bodies following a body cut in step 2 or 3 are held behind it
//!    along their rows ([`super::punched_followers`]).
//!
//! Steps 3 and 4 shorten a body's displacement along its own path; none of
//! the steps pushes a body sideways or back. A body's rows are linear in
//! its displacement and hold at the solve's displacement and at none
//! (where it starts), so they hold at any `λ·d`, `λ ∈ [0, 1]`: shortening
//! keeps every row the solve satisfied, with walls above all. A push along
//! another pair's normal does not: a first version of steps 3 and 4 moved
//! a light circle of a heavy crowd back along a diagonal contact normal
//! (0.8, 0.6) by 0.64, which took 0.38 off its height, through the floor
//! it had a row with (and nothing after repairs that: the position pass
//! corrects at most `margin/2` per axis).
//!
//! A punched body's motion is otherwise left as the solve made it: its rows
//! with other moving bodies assume both move by `v·h` (a bullet's row with
//! a free box it punched held the bullet in front of the box only because
//! the box moved as fast as the bullet). Step 2 runs again after the
//! position pass and the projection out of immovable bodies (which projects
//! along rows only: a crowd pushed a punched body 0.05, the correction's
//! bound, into a wall it had just been stopped at); steps 3 and 4 run on
//! the solve's displacements (the hold measures its rows against them), in
//! turn while a meeting stops a body: a body the hold stopped short can be
//! met by one that step 3 timed against its longer path.

use crate::collision::{Proxy, ProxyClass, shape_toi};
use crate::geometry::Toi;
use crate::math::{Scalar, Vec2};
use crate::solver::StepContext;
use crate::world::World;

use super::punched_followers::hold_followers_behind;

/// The most rounds of steps 3 and 4 in a substep
/// ([`World::cut_punched_motion`]): a round follows only one in which a
/// meeting stopped a body, so a row of 8 bodies, each met by the next once
/// the hold has stopped it, is stopped body by body; a longer row's
/// further meetings are left to the position pass and the next substep's
/// rows.
const HOLD_MAX_ROUNDS: u32 = 8;

impl<S: Scalar> World<S> {
    /// Keeps the velocities the narrow phase saw, for
    /// [`World::cut_punched_motion`].
    pub(super) fn remember_predicted_velocities(&mut self) {
        let context = &mut self.step_context;
        context.predicted_velocities.clone_from(&context.velocities);
    }

    /// Finds the punched bodies and the bodies beyond their proxies (step
    /// 1 of the [module docs](self)), cuts their motion at the immovable
    /// bodies they have no row with (step 2), stops them where they meet
    /// movable ones they have no row with (step 3) and holds the bodies
    /// following them (step 4).
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
        // query against every other proxy (movable ones too: a punched box
        // flew into the next box of a row it was never paired with); the
        // others take part as `Still`, which pairs with the escaping ones
        // only. Most substeps have no such body: they are looked for first,
        // and only then are the proxies copied.
        context.escape_proxies.clear();
        let escaping_reach = |i: usize, proxy: &Proxy<S>| {
            let body = self.slots[i].body.as_ref()?;
            let now = body.aabb();
            let later = body
                .shape
                .bounding_aabb_at(body.position + context.displacements[i]);
            let reach = now.union(&later).expanded(grow);
            let (lo, hi) = (reach.min(), reach.max());
            (!proxy.covers(lo, hi)).then_some((lo, hi))
        };
        let proxy_of = |i: u32| {
            context
                .proxies
                .binary_search_by_key(&i, |p| p.index)
                .ok()
                .map(|k| &context.proxies[k])
        };
        let any_escapes = context.punched.iter().any(|&i| {
            proxy_of(i).is_some_and(|proxy| {
                proxy.class == Some(ProxyClass::Dynamic)
                    && escaping_reach(i as usize, proxy).is_some()
            })
        });
        if any_escapes {
            // The escaping regions first, and the box round them all: a
            // proxy outside that box pairs with none of them and stays out
            // of the query (in a pile of 5000 falling balls a punched body
            // left its proxy in 12 of 59 substeps).
            let mut around: Option<(Vec2<S>, Vec2<S>)> = None;
            for &i in &context.punched {
                let Some(proxy) = proxy_of(i) else { continue };
                if proxy.class != Some(ProxyClass::Dynamic) {
                    continue;
                }
                if let Some((lo, hi)) = escaping_reach(i as usize, proxy) {
                    let grown = proxy.escaping_over(lo, hi);
                    let (lo, hi) = (
                        Vec2::new(grown.min_x, grown.min_y),
                        Vec2::new(grown.max_x, grown.max_y),
                    );
                    around = Some(match around {
                        Some((l, h)) => (l.min(lo), h.max(hi)),
                        None => (lo, hi),
                    });
                    context.escape_proxies.push(grown);
                }
            }
            let (lo, hi) = around.unwrap_or((Vec2::ZERO, Vec2::ZERO));
            for proxy in &context.proxies {
                if proxy.class.is_none()
                    || proxy.max_x < lo.x
                    || proxy.min_x > hi.x
                    || proxy.max_y < lo.y
                    || proxy.min_y > hi.y
                {
                    continue;
                }
                let i = proxy.index as usize;
                if proxy.class == Some(ProxyClass::Dynamic)
                    && context.punched_mark[i]
                    && escaping_reach(i, proxy).is_some()
                {
                    continue;
                }
                context.escape_proxies.push(Proxy {
                    class: Some(ProxyClass::Still),
                    ..*proxy
                });
            }
        }
        if any_escapes {
            context
                .escape_broad_phase
                .find_pairs(&context.escape_proxies, &mut context.escape_pairs);
            // Keep the pairs the main broad phase did not already find.
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
            punched_meetings,
            constraints,
            velocities,
            predicted_velocities,
            ..
        } = context;
        punched_meetings.clear();
        let paired = pairs.len();
        for (k, &(a, b)) in pairs.iter().chain(escape_pairs.iter()).enumerate() {
            if !(punched_mark[a as usize] || punched_mark[b as usize]) {
                continue;
            }
            let (movable_a, movable_b) = (
                inverse_masses[a as usize].is_positive(),
                inverse_masses[b as usize].is_positive(),
            );
            if movable_a && movable_b {
                // A pair without a row was predicted to stay more than the
                // margin apart along its normal; the solve closes it further
                // by at most the change of the two displacements along it,
                // at most its L1 norm. Within the margin: no meeting.
                if k < paired {
                    let change = (velocities[a as usize] - predicted_velocities[a as usize])
                        - (velocities[b as usize] - predicted_velocities[b as usize]);
                    if change.x.abs().add(change.y.abs()).mul(h) <= margin {
                        continue;
                    }
                }
                punched_meetings.push((a, b));
                continue;
            }
            for (mover, other) in [(a, b), (b, a)] {
                if punched_mark[mover as usize] && !inverse_masses[other as usize].is_positive() {
                    punched_obstacles.push((mover, other));
                }
            }
        }
        if punched_obstacles.is_empty() && punched_meetings.is_empty() {
            return;
        }
        punched_obstacles.sort_unstable();
        // `pairs` is sorted; the escape pairs come after it.
        if !escape_pairs.is_empty() {
            punched_meetings.sort_unstable();
        }
        let (mut with_row, mut meeting_with_row) = (false, false);
        for c in constraints.iter() {
            // Only a row with a punched end is in either list (most rows
            // are not: this check first).
            if !(punched_mark[c.a as usize] || punched_mark[c.b as usize]) {
                continue;
            }
            let (movable_a, movable_b) = (
                c.inverse_mass_a.is_positive(),
                c.inverse_mass_b.is_positive(),
            );
            let (list, found) = if movable_a == movable_b {
                (&mut *punched_meetings, &mut meeting_with_row)
            } else {
                (&mut *punched_obstacles, &mut with_row)
            };
            for key in [(c.a, c.b), (c.b, c.a)] {
                if let Ok(k) = list.binary_search(&key) {
                    list[k].1 = u32::MAX;
                    *found = true;
                }
            }
        }
        if with_row {
            punched_obstacles.retain(|&(_, other)| other != u32::MAX);
        }
        if meeting_with_row {
            punched_meetings.retain(|&(_, other)| other != u32::MAX);
        }
        let cut = self.cut_punched_at_immovable_partners(true);
        let (mut held, _) = self.stop_punched_meetings(cut);
        // Steps 3 and 4 in turn: a body the hold stopped short may now be
        // met by a body it has no row with (paired with it as a meeting),
        // which step 3 checked against its longer path. A ball at 50
        // units/s 0.11 behind a box 100× lighter that it had launched at
        // 86.9 units/s (apart: no row) towards a second box 0.3 from a
        // wall: the second box was cut at the wall, the first held behind
        // it after 0.3 of its 0.72, and the ball, whose 0.72 step 3 had
        // timed against the first box's, ended 0.30 inside it. A round
        // follows only one in which a meeting stopped a body, at most
        // [`HOLD_MAX_ROUNDS`] in all (the hold bounds its passes alike).
        let listed = self.step_context.punched_meetings.len();
        let mut rounds = 0;
        while held {
            let context = &mut self.step_context;
            hold_followers_behind(
                &context.constraints,
                &mut context.hold_links,
                &mut context.displacements,
                &context.uncut_displacements,
                &mut context.hold_rank,
            );
            rounds += 1;
            if rounds == HOLD_MAX_ROUNDS {
                break;
            }
            list_meetings_of_stopped(&mut self.step_context, listed);
            held = self.stop_punched_meetings(true).1;
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
    /// whether any body was cut.
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
                        begin_hold(
                            &mut context.uncut_displacements,
                            &mut context.hold_rank,
                            &context.displacements,
                        );
                    }
                    context.hold_rank[mover as usize] = 1;
                }
                any_cut = true;
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

    /// Step 3 of the [module docs](self): each punched body and each
    /// movable body it is paired with but has no row with, whose sweeps
    /// meet at `t` with motion into each other after it beyond half the
    /// slop: each of the two whose motion goes into the other is scaled to
    /// `t` along its path, and ranked 2 for [`hold_followers_behind`] (1 is
    /// a body cut at an obstacle). `held`: whether a body was already cut
    /// (and the displacements before the cuts kept); returns whether any
    /// body was cut or stopped, so that the hold is due, and whether this
    /// call stopped one.
    fn stop_punched_meetings(&mut self, held: bool) -> (bool, bool) {
        let half_slop = self.settings.linear_slop.half();
        let context = &mut self.step_context;
        let mut held = held;
        let mut stopped = false;
        for &(a, b) in &context.punched_meetings {
            let (ia, ib) = (a as usize, b as usize);
            let (Some(body_a), Some(body_b)) =
                (self.slots[ia].body.as_ref(), self.slots[ib].body.as_ref())
            else {
                continue;
            };
            let (da, db) = (context.displacements[ia], context.displacements[ib]);
            // Sweeps whose boxes do not meet cannot meet (most pairs: the
            // broad phase paired them within the margin and their
            // velocities before the solve).
            let swept_a = body_a
                .aabb()
                .union(&body_a.shape.bounding_aabb_at(body_a.position + da));
            let swept_b = body_b
                .aabb()
                .union(&body_b.shape.bounding_aabb_at(body_b.position + db));
            if !swept_a.overlaps(&swept_b) {
                continue;
            }
            let Toi::Hit { t, normal } = shape_toi(
                &body_a.shape,
                body_a.position,
                da,
                &body_b.shape,
                body_b.position,
                db,
            ) else {
                continue;
            };
            // Each body's motion into the other after the meeting (the
            // normal from a to b). Half the slop, as in step 2: an overlap
            // a resting contact may have is left to the next substep's row.
            let rest = S::ONE.sub(t);
            let into_a = da.dot(normal).max(S::ZERO).mul(rest);
            let into_b = db.dot(normal).neg().max(S::ZERO).mul(rest);
            if into_a.add(into_b) <= half_slop {
                continue;
            }
            if !held {
                held = true;
                begin_hold(
                    &mut context.uncut_displacements,
                    &mut context.hold_rank,
                    &context.displacements,
                );
            }
            for (index, into) in [(ia, into_a), (ib, into_b)] {
                // A body a spring pulls is left as the solve made it: the
                // spring solve put it where its springs' energy balances its
                // velocity, and holding it back (velocity kept) stretches
                // them. A light end of a stiff chain thrown hard, flung
                // through the heavy end in one substep, stopped there gained
                // 109 J in one substep (0.4 % of the throw's energy). Its
                // overlap, if any, is the next substep's row's.
                let sprung = || {
                    context
                        .springs
                        .rows
                        .iter()
                        .any(|row| row.a as usize == index || row.b as usize == index)
                };
                if into.is_positive() && !sprung() {
                    stopped = true;
                    context.displacements[index] = context.displacements[index].scale(t);
                    let rank = &mut context.hold_rank[index];
                    if *rank == 0 {
                        *rank = 2;
                    }
                }
            }
        }
        (held, stopped)
    }
}

/// Lists for step 3's later rounds the pairs of movable bodies without a
/// row in which neither body is punched but one was stopped short (held or
/// stopped at a meeting: ranked), after the first `listed` meetings (the
/// punched bodies' own, kept). A body stopped short is met by the bodies
/// behind it as a punched one is: a row of circles sliding up a wall at
/// 1 100-1 700 units/s, one stopped at its meeting with the next, the one
/// behind it (no row: it was slower) flew 0.32 into it.
fn list_meetings_of_stopped<S: Scalar>(context: &mut StepContext<S>, listed: usize) {
    let StepContext {
        pairs,
        escape_pairs,
        inverse_masses,
        punched_mark,
        punched_meetings,
        constraints,
        hold_rank,
        hold_links,
        ..
    } = context;
    punched_meetings.truncate(listed);
    let stopped = |i: usize| !punched_mark[i] && hold_rank[i] != 0;
    for &(a, b) in pairs.iter().chain(escape_pairs.iter()) {
        let (ia, ib) = (a as usize, b as usize);
        if punched_mark[ia] || punched_mark[ib] || !(stopped(ia) || stopped(ib)) {
            continue;
        }
        if inverse_masses[ia].is_positive() && inverse_masses[ib].is_positive() {
            punched_meetings.push((a, b));
        }
    }
    let added = &mut punched_meetings[listed..];
    if added.is_empty() {
        return;
    }
    added.sort_unstable();
    // The pairs with a row, found first and then taken out (marking them
    // in place would unsort the list under the search). The hold's link
    // list is free between its calls: it is rebuilt at each.
    hold_links.clear();
    for c in constraints.iter() {
        let (ia, ib) = (c.a as usize, c.b as usize);
        if !(stopped(ia) || stopped(ib)) {
            continue;
        }
        for key in [(c.a, c.b), (c.b, c.a)] {
            if let Ok(k) = added.binary_search(&key) {
                hold_links.push(u32::try_from(k).unwrap_or(u32::MAX));
            }
        }
    }
    for &k in hold_links.iter() {
        if let Some(pair) = added.get_mut(k as usize) {
            pair.1 = u32::MAX;
        }
    }
    if !hold_links.is_empty() {
        punched_meetings.retain(|&(_, b)| b != u32::MAX);
    }
}

/// Keeps the displacements before the first cut of the substep (the hold
/// measures its rows against them) and clears the ranks.
fn begin_hold<S: Scalar>(uncut: &mut Vec<Vec2<S>>, rank: &mut Vec<u32>, displacements: &[Vec2<S>]) {
    uncut.clear();
    uncut.extend_from_slice(displacements);
    rank.clear();
    rank.resize(displacements.len(), 0);
}
