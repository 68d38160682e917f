//! `geometry_differential`: arbitrary circles and boxes, a ray and a
//! displacement per shape; contacts, ray casts and times of impact in `Fx`
//! against the same code with the `f64` reference scalar and against the
//! geometry itself: hit/miss agreement outside a grazing band, distances,
//! points, normals and times of impact within the derived bounds, and
//! exact contact symmetry under swapping the shapes. The bounds and their
//! derivation are in `src/geometry_check.rs`.
#![no_main]

use clockwork2d_fuzz::geometry_check::{GeometryInput, check};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: GeometryInput| {
    check(&input);
});
