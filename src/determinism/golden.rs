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
            (60, 0x57b125dee57826ce, 0xc3f425a095e4a822),
            (120, 0x1e057c1b20677199, 0x67884c1553804c95),
            (180, 0xce4fd146b9d12e94, 0x36c6c39db3479209),
            (240, 0xec3e20ede8371b4c, 0xc6412f6961bbd175),
            (300, 0xc36d5aaec2e3d11a, 0xfef0fcb61174a6a9),
            (360, 0x505d4605bbfc9395, 0x0e8926022b4c8155),
            (420, 0x032b3d700ff3432d, 0x9ddbd3ff32c48d25),
            (480, 0xc2538fe3cf1bdf1b, 0xa43144c3b4aa0261),
            (540, 0x3b2552b52f9a48c7, 0xfd83f6beff23d30d),
            (600, 0x6ffbb5af9317f1f3, 0xf7b9c71d8ed00ca3),
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
            (540, 0xc101ab7d513c82eb, 0x72ab61630467a4c2),
            (600, 0x8011ddf698e650e3, 0x5ba5fe822fae545a),
        ],
    },
    GoldenScenario {
        name: "bullets_toi",
        checkpoints: &[
            (0, 0xee79d9d0212225b7, 0xcbf29ce484222325),
            (60, 0x81fcf1a823dbf388, 0x3e46ee840d29cd3b),
            (120, 0x4741f8aabb0056eb, 0x1bb931da7eb317d1),
            (180, 0x8b62936facd1e264, 0xa61386965b63ca2f),
            (240, 0x089bda3180e38925, 0x4560075624ac80a1),
            (300, 0xe8882a3d4744e9e5, 0xc33a36c75e6bfa3c),
            (360, 0x26900a4c6807891a, 0x79b725f6ad2e8dab),
            (420, 0xa5838a3e54faa573, 0xbf297ca76b7b62ed),
            (480, 0x442403b16c59dfb0, 0x84a7faf6438f5ce5),
            (540, 0x0481990e0028e560, 0x9c736790beda8412),
            (600, 0xb4f168a5ddf6d45b, 0x7b7187a2b2b66a7d),
        ],
    },
    GoldenScenario {
        name: "springs",
        checkpoints: &[
            (0, 0xcc5738024675872c, 0xcbf29ce484222325),
            (60, 0x6e9a2ca8a10559e5, 0x8c824326e2eeb902),
            (120, 0xcab0b57951c70ec2, 0xe58bff1da4d2749a),
            (180, 0xcce0ed783e445e60, 0x969077e015365c68),
            (240, 0x0172078842a6c7f5, 0x1cecfce47d193a70),
            (300, 0xea93a5c48b00093d, 0x1f7c36eb4c9c7863),
            (360, 0x7736f2d21596c35e, 0x47e95aa02dda4b73),
            (420, 0x45245e22801822aa, 0x9cb0eaacecbbcc5a),
            (480, 0xf7223b941f146c78, 0xe27167b22e26d199),
            (540, 0xc1683606e6bdb515, 0x6f83ea18dd4caf08),
            (600, 0xafbfab95a9309d15, 0x7534c19ecfad3f4f),
        ],
    },
    GoldenScenario {
        name: "ropes_chain",
        checkpoints: &[
            (0, 0x996fd0c57043a31c, 0xcbf29ce484222325),
            (60, 0x17e2d5623e0c6871, 0xfb75ebd068f7a195),
            (120, 0x6f9e6203c7d5ee9c, 0x9a3fa98ca3cc0505),
            (180, 0xce536f00b972ec18, 0x6c486e68f0280065),
            (240, 0x9e29afa39edb58b1, 0x514820a0e85d3ad5),
            (300, 0xfde9b775e8da92c4, 0x4a964599a8f09a45),
            (360, 0x2a790e181e9031e5, 0x6c9e5105aea353d8),
            (420, 0x75026598c3f1437e, 0xec0ed1e63ef20ddd),
            (480, 0x5d09e2e802a075e4, 0xdf5ade70c0501b62),
            (540, 0x4c693b59cf98ba0a, 0x99142003787828fa),
            (600, 0x149b05f977b73565, 0x38b23a0a5b7c3b12),
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
            (60, 0x89f1a3d286c428de, 0xc6588c5175503687),
            (120, 0xdac9b2cbcda2adee, 0x6afdd7750415e087),
            (180, 0x2214466e899c9d62, 0xc0298a49df5806ab),
            (240, 0x11b3a2fdee6920ff, 0x251a76751d16aa08),
            (300, 0xc7036e35a00f351d, 0xdf52d4690d5d107c),
            (360, 0x89ea48f70e19a90a, 0x71b230258b832482),
            (420, 0x53e6c7c4cf7bf05d, 0x02c8e6dece89d153),
            (480, 0xef0b50e70b8ced9b, 0xe07b391e1a283df3),
            (540, 0xd7ec5dfda834cff8, 0x4221d09a5200cf17),
            (600, 0x1eb5ab54728ed7a6, 0x7bd2cbc1beabe6f5),
        ],
    },
    GoldenScenario {
        name: "bounds_extreme",
        checkpoints: &[
            (0, 0x32dcf2730386f627, 0xcbf29ce484222325),
            (60, 0x33bf8cf301696be7, 0xc165294d9595b7a1),
            (120, 0x9a1e9ca77411797a, 0xc9d5a9c57be3dd03),
            (180, 0x7afc68293b3d60b0, 0xbb63c249d91ef0c9),
            (240, 0x65c153c8f13daae9, 0x360df70eb4bccba1),
            (300, 0x9e4bc8d1533e52b4, 0x25c0f34eb4552747),
            (360, 0xdc493e9cd912e41e, 0xe9005c05db80ade2),
            (420, 0x2d58c3fa2631e293, 0x4d4a3a806c802726),
            (480, 0x35255c341e7b14e2, 0x7ed4ab1894759494),
            (540, 0x277828810bd7faa6, 0xaa31d09af2d3015e),
            (600, 0x746953bf7bac2e1d, 0xe1dfe4c60b87d925),
        ],
    },
];
