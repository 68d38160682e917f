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
            (60, 0x57b125dee57826ce, 0x8df9a342628d01fa),
            (120, 0x1e057c1b20677199, 0x3e0a9934c238eded),
            (180, 0xce4fd146b9d12e94, 0x3b89337a224ccc81),
            (240, 0xec3e20ede8371b4c, 0xe6166bfbe5d25b6d),
            (300, 0xc36d5aaec2e3d11a, 0x4b020cc04b3f4d01),
            (360, 0x505d4605bbfc9395, 0x264068b6d74e04ed),
            (420, 0x68ce81dcfbe408fd, 0x043177836cf0bc77),
            (480, 0xc2538fe3cf1bdf1b, 0xd0748eae055140ed),
            (540, 0x3b2552b52f9a48c7, 0xd860fde4a5d7b581),
            (600, 0x6ffbb5af9317f1f3, 0x7a66e345199d558f),
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
            (180, 0x10811348391cca3d, 0x6c486e68f0280065),
            (240, 0x2cfadcfa0bb61c3a, 0x514820a0e85d3ad5),
            (300, 0x1f41ff9510a3529c, 0x4a964599a8f09a45),
            (360, 0x61838bd62d93e2ce, 0x6c9e5105aea353d8),
            (420, 0xc99530c61c7bcba3, 0x7849f80c6d652729),
            (480, 0xe8869e572a9916ef, 0xee8403d81d67eefe),
            (540, 0xe78972ab5fadaa9e, 0x3b48876822138b56),
            (600, 0x418b8422266dc5d2, 0x38828e40cbdbb02e),
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
            (360, 0x3cd727d842fff6d6, 0xf2ab2b50fbae9383),
            (420, 0xa9555bb91d87ec71, 0x1440ec0a029c8394),
            (480, 0xd2a5f36eacc271f0, 0xd623ede262034080),
            (540, 0x61c680418bf889d6, 0x6d9e3c3245191815),
            (600, 0xcec97c1b672cd8ff, 0x449072782db66d17),
        ],
    },
    GoldenScenario {
        name: "commands_churn",
        checkpoints: &[
            (0, 0xfb2aa981e2618356, 0xcbf29ce484222325),
            (60, 0x89f1a3d286c428de, 0x8ac0a0ecde1b5677),
            (120, 0xdac9b2cbcda2adee, 0x511de2f6c749f019),
            (180, 0x2214466e899c9d62, 0xf0c8c4b9798460de),
            (240, 0x11b3a2fdee6920ff, 0x465d43b1b627397d),
            (300, 0xc7036e35a00f351d, 0x1bbd5e910dec5f64),
            (360, 0x89ea48f70e19a90a, 0x5acaa9a83194f1da),
            (420, 0xaa6f42f631a74402, 0x75605bded02f2316),
            (480, 0x012d2c9b3dd6382b, 0x65d21cabded2dc8f),
            (540, 0x6a57b7e6eaf60d31, 0xab2b3d9d9c63f3e8),
            (600, 0xb6d8d7122dc8b10a, 0x680d5e6daaa7399c),
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
