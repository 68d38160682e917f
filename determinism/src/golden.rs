//! Golden checkpoints of the determinism suite. Generated: do not edit by hand.
//!
//! Regenerate with
//! `cargo run --release -p clockwork2d-determinism --example determinism_suite -- --update-golden`
//! and name the behaviour change in CHANGELOG.md.

use super::GoldenScenario;

/// `(tick, state hash, probe digest)` of every scenario at every checkpoint.
pub const GOLDEN: &[GoldenScenario] = &[
    GoldenScenario {
        name: "stack_sleep",
        checkpoints: &[
            (0, 0x879b22e3511882c1, 0xcbf29ce484222325),
            (60, 0x291dad50f7422d7f, 0x7ae470169ef5147f),
            (120, 0x840d2725ebfeb7a0, 0xa06240e8c20855d0),
            (180, 0x492ccc45531ca1a1, 0x099b4a243a6d1dda),
            (240, 0x10b7e93193c5ac39, 0xdf7512512eb4d3d8),
            (300, 0x95682fefaf1dc1bf, 0xc23b7ac7259e0f82),
            (360, 0x3895d460ec9833c4, 0xd37c58b44f124260),
            (420, 0xebbcb847a4d605e5, 0x7bdeb0a55b15b57b),
            (480, 0xa122c173e1001f8c, 0x1528c2691fd67095),
            (540, 0x05891f76f3a93930, 0xff101e8371153e09),
            (600, 0xddf2e70967f12cd5, 0xd62ff531f2635ed7),
        ],
    },
    GoldenScenario {
        name: "pyramid",
        checkpoints: &[
            (0, 0xf21961f039fca482, 0xcbf29ce484222325),
            (60, 0x4a90e55b4624bf18, 0x123ebb41544aff8f),
            (120, 0x31583d04ca5525e1, 0xeaed4460237676bf),
            (180, 0x05eac2521de9c140, 0xf52f9c0b160736ef),
            (240, 0xcde7282a951644c8, 0xdc12856aec77f01f),
            (300, 0xab3108e2ca7fcd0a, 0x489a654dc6b4524f),
            (360, 0x0cd74fc3de17f47d, 0xc2155fefce490d7f),
            (420, 0x367c73fffd28eada, 0x360f4451b993d1af),
            (480, 0x8a401f0e9b913a7a, 0x7e008666be7ef2d3),
            (540, 0xd3e9a18862feb741, 0xd0709be13c76d65f),
            (600, 0x1e5e200f5dbb7159, 0x874fba348501a48f),
        ],
    },
    GoldenScenario {
        name: "bullets_toi",
        checkpoints: &[
            (0, 0xee79d9d0212225b7, 0xcbf29ce484222325),
            (60, 0xddfc543d1d7e60d8, 0xc4d425fb6c625438),
            (120, 0x454166d30b8afc72, 0x4d1c2f00be53ac5b),
            (180, 0xa4cb7705d085f57b, 0x19b70399f538e6c2),
            (240, 0x4d02c013306fcdae, 0xb0cec0b0355c15cc),
            (300, 0xee9c12035af91d18, 0xffeb3f7982dcd88b),
            (360, 0xb98d58d8468a4356, 0xb73ebf0ca6cf3c6b),
            (420, 0x586aa0580e74ae14, 0xbb4fe2dcd780a261),
            (480, 0xdf93c14ea692d608, 0xe4b9f656a93ddacc),
            (540, 0x95375ca9fbfdea22, 0x8be70b0ac0a104d0),
            (600, 0x7dae098111cfe80d, 0x11f8b91e167e2567),
        ],
    },
    GoldenScenario {
        name: "springs",
        checkpoints: &[
            (0, 0xcc5738024675872c, 0xcbf29ce484222325),
            (60, 0x746acbe94f9e850e, 0x8c824326e2eeb902),
            (120, 0x06bc0a15d1108054, 0xe58bff1da4d2749a),
            (180, 0xce4fab6964e8d28f, 0x969077e015365c68),
            (240, 0x8c1b830bc0d339bb, 0x1cecfce47d193a70),
            (300, 0x9d31b315d5f15e07, 0x1f7c36eb4c9c7863),
            (360, 0xbcefa0d81e7551aa, 0x47e95aa02dda4b73),
            (420, 0x1e8067cb5e895645, 0x9cb0eaacecbbcc5a),
            (480, 0x32397eb56c775dbc, 0x1449bb70f8924e8a),
            (540, 0x812dddf1c97465c3, 0x790e765298efb771),
            (600, 0x8202ea1f2af32e7d, 0xd3f48b187f8c8f0c),
        ],
    },
    GoldenScenario {
        name: "ropes_chain",
        checkpoints: &[
            (0, 0x996fd0c57043a31c, 0xcbf29ce484222325),
            (60, 0x80588691fafced42, 0xfb75ebd068f7a195),
            (120, 0x96daf45d2ea6e912, 0x9a3fa98ca3cc0505),
            (180, 0x8d9e2c7b2b31da88, 0x6c486e68f0280065),
            (240, 0xc4e813793017e0ba, 0x514820a0e85d3ad5),
            (300, 0x3d1ea1ad702634e9, 0x4a964599a8f09a45),
            (360, 0x2a4d8093d3fc3784, 0x6c9e5105aea353d8),
            (420, 0xa3cb7950bac28448, 0x8f4e52f3e3ffef17),
            (480, 0xcc926ce48ab56ab2, 0xe749fb5b603b3e78),
            (540, 0xe49a16671f97f5d1, 0x67265c9cb23bcf80),
            (600, 0x9a74effe6dee54f4, 0xc889047979913a08),
        ],
    },
    GoldenScenario {
        name: "grapple_rays",
        checkpoints: &[
            (0, 0xa4c5c69f6e84c6d3, 0xcbf29ce484222325),
            (60, 0xde3353da3854eb44, 0xe38948aa78dd6e6f),
            (120, 0x2ba3cbffb1f25b77, 0xfec7f849837e4fa3),
            (180, 0x6ede61b7fd7780ff, 0x8a9176e4dff94472),
            (240, 0xc51dc92860dc5c58, 0xac9d82212eee518b),
            (300, 0x2d82c5a13f9e66fe, 0xa95405b006169df6),
            (360, 0x07ba4a79922b6530, 0x8cebdf0943b80edf),
            (420, 0xadc3a8a2d7d581da, 0x9f7fb9bbe83fbcc0),
            (480, 0xa797e6a7c4be0f08, 0xb0b6f6b1e982266b),
            (540, 0x8074594e5cc5c49b, 0x14509d68b3dd5fe5),
            (600, 0x2db7ee2bad3c86de, 0xd11d8788a8ad0afe),
        ],
    },
    GoldenScenario {
        name: "commands_churn",
        checkpoints: &[
            (0, 0xfb2aa981e2618356, 0xcbf29ce484222325),
            (60, 0xdc532f38ba04464a, 0xaf83f0b308c19bf9),
            (120, 0xcc84587effa4c81c, 0x12fb2048945b5ec2),
            (180, 0x885f42c269c32bff, 0x093972ea033bd1c1),
            (240, 0x9ab19a0690015c42, 0x8279f13984aaa8bc),
            (300, 0xbbf66501340fc3bf, 0x734d6a0ecfe37882),
            (360, 0x47d8315e1c72f85b, 0x029d040aa11226a0),
            (420, 0x9210d944ff91b7ae, 0x843f9053c2b497d4),
            (480, 0x7352ac2f4a9393d4, 0x2f8bdd6f58a920ee),
            (540, 0x9894b1b837fc37b5, 0x32e68b5ceb7a6e48),
            (600, 0x58c636b00254cfb9, 0xd93c070f672b875b),
        ],
    },
    GoldenScenario {
        name: "bounds_extreme",
        checkpoints: &[
            (0, 0x32dcf2730386f627, 0xcbf29ce484222325),
            (60, 0xb1ed0c2ee0aad0e4, 0xaf08d91aa1a0ba8e),
            (120, 0x7c88b7bfc7b1681d, 0x3517ab3031a1ff58),
            (180, 0xdba2948201060b41, 0xed5a3c3ae8125a86),
            (240, 0xfd2806e2d439f4da, 0xcbc6a1e4f1a89168),
            (300, 0xad84b6f1d6acf415, 0x60afa10ac40aee2c),
            (360, 0x9f75ffdae2e3609b, 0x518ed9ff41ce0f13),
            (420, 0xfa2022287acc7393, 0x80012ef3d90d0609),
            (480, 0x91d95de144f784e6, 0x9645dba909ba156a),
            (540, 0xf1a2a58b37f05033, 0x3812cb0aa3569e7c),
            (600, 0x29eee9fde5a63c6e, 0x314e520edbe51e9d),
        ],
    },
];
