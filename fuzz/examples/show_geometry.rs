//! Prints a `geometry_differential` input as the target decodes it, then
//! checks it (panicking like the target on a finding):
//! `cargo run --manifest-path fuzz/Cargo.toml --example show_geometry -- FILE`.

use arbitrary::{Arbitrary, Unstructured};
use clockwork2d_fuzz::geometry_check::{GeometryInput, check};

fn main() {
    let path = std::env::args().nth(1).expect("usage: show_geometry FILE");
    let bytes = std::fs::read(&path).expect("readable input");
    let input =
        GeometryInput::arbitrary_take_rest(Unstructured::new(&bytes)).expect("decodable input");
    println!("{input:#?}");
    check(&input);
    println!("no finding");
}
