//! Prints a `world_commands` input as the target decodes it, then plays
//! it (panicking like the target on a finding):
//! `cargo run --manifest-path fuzz/Cargo.toml --example show_script -- FILE`.

use arbitrary::{Arbitrary, Unstructured};
use clockwork2d_fuzz::world_script::{Script, run};

fn main() {
    let path = std::env::args().nth(1).expect("usage: show_script FILE");
    let bytes = std::fs::read(&path).expect("readable input");
    let script = Script::arbitrary_take_rest(Unstructured::new(&bytes)).expect("decodable input");
    println!("{:#?}", script.settings);
    println!("settings as stepped: {:#?}", script.settings.affordable());
    for op in &script.ops {
        println!("{op:?}");
    }
    run(&script);
    println!("no finding");
}
