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
            (60, 0x34edb3bdeb06c026, 0xd456077717132544),
            (120, 0xae21462cb9b22947, 0x224c2391167e2b06),
            (180, 0x6e2acff3bd495f9e, 0xf7ca629525f5dc1c),
            (240, 0x5878518d5101bc76, 0x898d4ded121c5dfe),
            (300, 0x4531c5b948cd3de0, 0x7b988d3c28c0f794),
            (360, 0xb0ee081d8fcc23f3, 0xe5fc7a63d612daf6),
            (420, 0xd3f2c611f57ad4c5, 0x25094de6355d1c86),
            (480, 0x62a910488d15e2c6, 0x80db7f2f95ba6049),
            (540, 0xa34810cc47772ce2, 0x747d507ad672b035),
            (600, 0x77391928a214e0e9, 0xd6f702fb3fc83f2b),
        ],
    },
    GoldenScenario {
        name: "pyramid",
        checkpoints: &[
            (0, 0xf21961f039fca482, 0xcbf29ce484222325),
            (60, 0x257c8bc48706371b, 0xf7662306bc1fae41),
            (120, 0xf5f0ee99d541c636, 0xc7bc288b9b3ede11),
            (180, 0xeff69e40b6fb5df3, 0x0c703db0ae2b14e1),
            (240, 0x6386fa5c5cdb760b, 0x38d715b5f668a2b1),
            (300, 0x0fa519b10df3b1b5, 0xf2a859e9e0dad781),
            (360, 0x758213cf9c770bf2, 0xce71d7c1b2940351),
            (420, 0x0f548ec7dc413bc5, 0x0336b3fb6ca57621),
            (480, 0x7f216b5e61102bad, 0xec7d7c3e46346e59),
            (540, 0xa43ccdf3df7de8f2, 0x17b7464018e97634),
            (600, 0xca2b51f4c2a4a3ea, 0x26dc42badee3097c),
        ],
    },
    GoldenScenario {
        name: "bullets_toi",
        checkpoints: &[
            (0, 0xee79d9d0212225b7, 0xcbf29ce484222325),
            (60, 0x801670f0db100884, 0xc4d425fb6c625438),
            (120, 0x0731354834528f61, 0x4d1c2f00be53ac5b),
            (180, 0xc2a9ea5f46530208, 0x19b70399f538e6c2),
            (240, 0x4a39ca5f4a52b3be, 0xe28ff2ae0469de9b),
            (300, 0x4d137fef92235856, 0x9b4fbfc3bb807c42),
            (360, 0x38688f165513cfd5, 0x2f64923af3ed4e90),
            (420, 0x86b3fd0de4bdb198, 0x8eb899f13538d443),
            (480, 0x66ab6cbee63ac0ad, 0x4951da8c264b8fb8),
            (540, 0xdbc78b16e6580a3d, 0xc60e0ac165be7d34),
            (600, 0x02198d0048017a3e, 0x5785d42a26d0138e),
        ],
    },
    GoldenScenario {
        name: "springs",
        checkpoints: &[
            (0, 0xcc5738024675872c, 0xcbf29ce484222325),
            (60, 0xb4d00da6f7c7e873, 0x8c824326e2eeb902),
            (120, 0xbbe23919c67800a3, 0xe58bff1da4d2749a),
            (180, 0xf7cfa4c0aa6acd5d, 0x969077e015365c68),
            (240, 0x8afdc216cf0454ca, 0x1cecfce47d193a70),
            (300, 0x336b45abe22827e3, 0x1f7c36eb4c9c7863),
            (360, 0x4ef1903be0248c1c, 0x47e95aa02dda4b73),
            (420, 0xfb7599d793b42584, 0x9cb0eaacecbbcc5a),
            (480, 0xca75148d7020ae74, 0x1449bb70f8924e8a),
            (540, 0x41286922d2e166bf, 0x88c115e786959875),
            (600, 0xf431b399bf6a1644, 0x02078b57ef02ed90),
        ],
    },
    GoldenScenario {
        name: "ropes_chain",
        checkpoints: &[
            (0, 0x996fd0c57043a31c, 0xcbf29ce484222325),
            (60, 0xc4ac7126c061a28a, 0xfb75ebd068f7a195),
            (120, 0xe3c9cbaadab250ba, 0x9a3fa98ca3cc0505),
            (180, 0x7840d108ec3b2070, 0xfedf637293995a86),
            (240, 0xb845ed6788206ba0, 0x0e02083356ef485e),
            (300, 0x00c65a116e4206e8, 0x4b158d8f07c086b6),
            (360, 0x5236630f38105a17, 0x7be08e23622079ff),
            (420, 0x6ab2163d290a9bf8, 0x50f81313bca0c205),
            (480, 0x7401fca48a449669, 0xd11eea44f11804ed),
            (540, 0x9fbd31faa940142d, 0xb2cde08ee4c140dd),
            (600, 0x148f604f59272f1c, 0xb6d32ec8926869cd),
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
            (360, 0xae48dfe0d32cfd1d, 0xe0c0d1a7fd2702c7),
            (420, 0xcc673342e547257e, 0xd0fa7a85c119c86b),
            (480, 0x99350e6a0cb1873a, 0xd3baa02c59fd2fb8),
            (540, 0x7d2c7911abc7d26e, 0xbded32bf8ff27310),
            (600, 0x6ece85074d8cc88b, 0xd626b79a3a4da2fe),
        ],
    },
    GoldenScenario {
        name: "commands_churn",
        checkpoints: &[
            (0, 0xfb2aa981e2618356, 0xcbf29ce484222325),
            (60, 0x5ec6afd8a27285ba, 0x470dc36907f8e11c),
            (120, 0xd8af27b7b1219130, 0x58fd3062fc11ba63),
            (180, 0x2764094b773e329c, 0x82929ce0727463a8),
            (240, 0xd5b74ff07a43e182, 0xadcbed383245a2f6),
            (300, 0x33e3afcf72924a87, 0x385f8f1123c6c4df),
            (360, 0x4f01aa4505671fea, 0xc5428b57ba1eff2d),
            (420, 0xf3d593f72e816df9, 0x8f956447562939a8),
            (480, 0xa05114507fd1e97c, 0x3c8c81280e528287),
            (540, 0x6bace9a5852aad9a, 0x402e1832070cd737),
            (600, 0xb66b93dd0716af9d, 0x1ed9c956796a0cbd),
        ],
    },
    GoldenScenario {
        name: "bounds_extreme",
        checkpoints: &[
            (0, 0x32dcf2730386f627, 0xcbf29ce484222325),
            (60, 0x45f2a955329a37f9, 0xbbdbb1e6818f5d0a),
            (120, 0x252f1e3f8385e8fe, 0xc42c1c2d19198387),
            (180, 0x55d66e7ac68b7f9f, 0x6180d9bf39b32077),
            (240, 0x466fec63b20540bd, 0x29116a09fb4c0e35),
            (300, 0xaf8082ac3f500f55, 0xcbbaab48e32f24fb),
            (360, 0xbd77e642e5a593ed, 0x27ebf862750f625e),
            (420, 0x6903ce42154a1600, 0x51cc87582099b9cc),
            (480, 0x99597a79c5e46145, 0xb977daa24fbdb6de),
            (540, 0x03147957f9a7f78c, 0xae3889a37a761ad2),
            (600, 0x2c10f97858686586, 0x72402bb7ea12254b),
        ],
    },
];
