//! Measures how closely the fixed-point (`Fx` = I32F32) geometry queries agree
//! with the same algorithms run in `f64`, over seeded random inputs.
//!
//! `cargo run --release --example agreement`
#![allow(clippy::float_arithmetic)]

mod contacts;
mod rays;
mod rng;

fn main() {
    println!("| query | cases | max abs error (Fx vs f64) | mean abs error |");
    println!("|---|---|---|---|");
    contacts::report();
    rays::report();
}
