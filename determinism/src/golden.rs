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
            (60, 0x872c513b0b7d9b8c, 0xd456077717132544),
            (120, 0xce67a18468556031, 0x224c2391167e2b06),
            (180, 0x385172ebbb0be8f4, 0xf7ca629525f5dc1c),
            (240, 0xb3e0c56c93e262bc, 0x898d4ded121c5dfe),
            (300, 0xac306599f8a5ed5e, 0x7b988d3c28c0f794),
            (360, 0xa47dea4a6cc6fab5, 0xe5fc7a63d612daf6),
            (420, 0xfbde06a10bab2da3, 0x25094de6355d1c86),
            (480, 0x3f0a7d80719ca3af, 0x88f767ec7151c6b5),
            (540, 0xa523d196e6d9373b, 0x492e8fbd37992a69),
            (600, 0x0d7ca5f1651ddb79, 0x7f4c6571d80705f7),
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
            (240, 0x33dbe5d74c07fb13, 0xfe69db91784390f0),
            (300, 0xffaf059ed554384a, 0x7e82dc386cc8ae85),
            (360, 0x4b35e1ee878a57ea, 0xd592c54f1ee6fff9),
            (420, 0x16dce3573f151ae8, 0x4b8273c2b3211af2),
            (480, 0x33a3348970c0c0fa, 0x5d1fbbb661b33995),
            (540, 0x77448e66361767d5, 0x47b01a67699c2af6),
            (600, 0x9c0008799d6fa3b5, 0xf0e93f7b31f8c3e9),
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
            (60, 0xcf56d91cfc446ffc, 0xfb75ebd068f7a195),
            (120, 0xd164a960840d8174, 0x9a3fa98ca3cc0505),
            (180, 0xa55940d77f38cd0f, 0xa71a2b609aac2616),
            (240, 0xbf8a7cdbabcc2f87, 0x1898ac1a7aa30eee),
            (300, 0x70c45b6d6ef93332, 0x506b67fc165b5846),
            (360, 0xd0cbe7fec3671546, 0xff05a6d2c0740d0f),
            (420, 0x887117245fb873ac, 0xf65c46feddc471ec),
            (480, 0x8be0fd800256833f, 0x707ec38ca82bec47),
            (540, 0xdb3c376c43359799, 0x5efabc7e6ffaddf7),
            (600, 0x37ad3267777175a2, 0xce82e4ac712290a7),
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
            (360, 0x5673107ebf72d875, 0x9ce56d9600821611),
            (420, 0x04fb29b254edb43e, 0x7db9a2e275d6f6dc),
            (480, 0x55596bd15d4fdcab, 0xc20caad80911c8a9),
            (540, 0x7de7b053e502aad2, 0x4df69bbe07f70bfa),
            (600, 0x713c915aa3845361, 0xa67339cbe69b69b5),
        ],
    },
    GoldenScenario {
        name: "commands_churn",
        checkpoints: &[
            (0, 0xfb2aa981e2618356, 0xcbf29ce484222325),
            (60, 0xa417f9d3b92fc600, 0x1d73827d3187f2a1),
            (120, 0xd7f49a71811492a2, 0xebfc7fa2f2485cfa),
            (180, 0xbf14f6c8e2afd730, 0x760600f63ad1bea9),
            (240, 0x10d118f6f07d01d0, 0x28238f6450c85e54),
            (300, 0xcb46625dd6f3f462, 0xd6bda6c245f93b9a),
            (360, 0xce13aabe17a51c41, 0xdbd45595789c61be),
            (420, 0x49ce84ae6fb534c3, 0x895673027ff846e9),
            (480, 0xd6b6a8b6da81a428, 0x5821206dad789007),
            (540, 0x647eedbbb17cd9d3, 0x0160e728d6354f0e),
            (600, 0xfed16489839598ab, 0x3695d17a6fe31f32),
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
            (480, 0x88e1b3a373aca466, 0x9645dba909ba156a),
            (540, 0x799fd0387dae10a7, 0x3812cb0aa3569e7c),
            (600, 0x6e35bd76da65d8b2, 0x314e520edbe51e9d),
        ],
    },
];
