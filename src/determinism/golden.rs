//! Golden checkpoints of the determinism suite. Generated: do not edit by hand.
//!
//! Regenerate with
//! `cargo run --release --bin determinism_suite -- --update-golden`
//! and name the behaviour change in CHANGELOG.md.

use super::GoldenScenario;

/// `(tick, state hash, probe digest)` of every scenario at every checkpoint.
pub const GOLDEN: &[GoldenScenario] = &[
    GoldenScenario {
        name: "stack_sleep",
        checkpoints: &[
            (0, 0x879b22e3511882c1, 0xcbf29ce484222325),
            (60, 0x21ee763f44e9f08a, 0xb23685d0dca89184),
            (120, 0x7c9ff554a819a2e3, 0x59e88eceb6fe43c6),
            (180, 0x3d1651869f563712, 0x5b373c5d4707e25c),
            (240, 0x64c291bde51b22da, 0x7d424c1b9cb264be),
            (300, 0xfd219486b42ff218, 0x4a54daeea7ff27d4),
            (360, 0x000e8781a5ba66af, 0x8c79c553a92a7fb6),
            (420, 0x5d0f299bb751e3b0, 0xca9db4cfd206c4c6),
            (480, 0xbcae61c16fa42f4e, 0xa19265375d0a767b),
            (540, 0x36d5bf3c242c27fa, 0x2ad610c84691c963),
            (600, 0x27dafb01c65cf1a9, 0xd2690af78bde8f95),
        ],
    },
    GoldenScenario {
        name: "pyramid",
        checkpoints: &[
            (0, 0xf21961f039fca482, 0xcbf29ce484222325),
            (60, 0x546779d1a8b53532, 0x74f8456d892dad79),
            (120, 0xb1a3c4e3529a93c3, 0x99d837c916284fc9),
            (180, 0x0e196b4b6e06057a, 0x4b586709aab9f119),
            (240, 0x31bd5f474706bf82, 0x73fa5e58bb9d6169),
            (300, 0x33f920692cca2cb4, 0xa6842b2b7ba470b9),
            (360, 0xfa1483bd8c2ace57, 0x359db8afe307ef09),
            (420, 0xcf62d8b4040a5324, 0x25247f0ca5b7ac59),
            (480, 0x99e0be15ff99c799, 0xe14328266b0dcad1),
            (540, 0xc101ab7d513c82eb, 0x5db06c8d272bed02),
            (600, 0x8011ddf698e650e3, 0xc606da269bcd689a),
        ],
    },
    GoldenScenario {
        name: "bullets_toi",
        checkpoints: &[
            (0, 0xee79d9d0212225b7, 0xcbf29ce484222325),
            (60, 0xaa7e97d77bf07233, 0xbcd597ff6789d6bf),
            (120, 0x4e05ddb16e255d20, 0x1bd070c887e88ad7),
            (180, 0xfea0c275be41acff, 0xc06872feda15972b),
            (240, 0xe320c8a43727109f, 0x64780ed4349f2696),
            (300, 0x09e1d7d1697f3b2a, 0xda781ab69122ca15),
            (360, 0xddea9a8cc0b3a4a5, 0x6fdc18feb763bb31),
            (420, 0x9a9a4d4ce8b22cbb, 0xfd2173aeda959a3e),
            (480, 0x3971d4af018de6db, 0x67a3eb6fdd976826),
            (540, 0x81039d3eed832281, 0x9c7bf9c6080ddb47),
            (600, 0xdd1a7b9b07b55039, 0x947aca005b9479a1),
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
            (180, 0x6c321959acc607f7, 0x6c486e68f0280065),
            (240, 0x5a5ce96356019312, 0x514820a0e85d3ad5),
            (300, 0x6f940020b4b70060, 0x4a964599a8f09a45),
            (360, 0x3c6c9bf71f71ea37, 0x6c9e5105aea353d8),
            (420, 0x98a2ab19afa629b5, 0x400af14040f5cb30),
            (480, 0x5fce38c89220d431, 0x6f6d43ac3d6ca4e6),
            (540, 0xe0780e63f3df4b61, 0xaa707b3d286a64be),
            (600, 0x319eb4bcb3c15c25, 0x7ce8487df194d516),
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
            (360, 0xaebac1a858e91b21, 0xb4d0cc9d39259f55),
            (420, 0xa9ab91c536b6d31e, 0xa0ecefe85664688b),
            (480, 0x62b8f822931d219e, 0xd711c17f8415d59c),
            (540, 0x1d87a6ea09500f92, 0xe6d066fc65d3376b),
            (600, 0x289352092eaeb877, 0x6040ae22e7e1aee5),
        ],
    },
    GoldenScenario {
        name: "commands_churn",
        checkpoints: &[
            (0, 0xfb2aa981e2618356, 0xcbf29ce484222325),
            (60, 0xf735a04c25c9d8de, 0x4b920792c91ffedb),
            (120, 0xd37846d70ac02d2d, 0xf88a79d97932fb68),
            (180, 0xf92949aa753f2973, 0xb42e3d92b139b7de),
            (240, 0x337019f50906db99, 0x54aad7eb76e0294c),
            (300, 0xbc0312f03c8964d5, 0x4de553e9456c6f23),
            (360, 0x49410b5b770e3aed, 0x7a45443f124d5d67),
            (420, 0xfbd5208725922c4e, 0x4444b77f7870855f),
            (480, 0xe53b7f5b044d15d5, 0x4ee696582c4b0f6c),
            (540, 0x7cf72c1a801a87a6, 0x6767cb681c54f420),
            (600, 0xa7bcddc22f9cf1e8, 0x6ed61b21ec096bdc),
        ],
    },
    GoldenScenario {
        name: "bounds_extreme",
        checkpoints: &[
            (0, 0x32dcf2730386f627, 0xcbf29ce484222325),
            (60, 0x33bf8cf301696be7, 0xaf08d91aa1a0ba8e),
            (120, 0x9a1e9ca77411797a, 0xd78a6bd9c4b941f6),
            (180, 0x7afc68293b3d60b0, 0x78de61cb420994aa),
            (240, 0x65c153c8f13daae9, 0xfae85ab922035726),
            (300, 0x9e4bc8d1533e52b4, 0xc4ba5aa620c7e0e8),
            (360, 0xdc493e9cd912e41e, 0x9f91942ff880f99d),
            (420, 0x2d58c3fa2631e293, 0xc2261f37676e83a5),
            (480, 0xc86cece2339625de, 0x7a80339481013d27),
            (540, 0x071cddfb1deaf4bf, 0x22a6f0ec3d0479dd),
            (600, 0xc248834a5837d2ac, 0x6d81a8130a4772f8),
        ],
    },
];
