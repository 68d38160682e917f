//! [`Colour`]: the fixed set of colours every picture is drawn with.
//!
//! Drawing uses these colours only and no anti-aliasing, so every pixel of a
//! frame is exactly one palette entry: a GIF needs no colour quantisation
//! (the frame's indices are exact), 16 entries fit in 4 bits, and the LZW
//! coder sees long runs. That is what keeps the committed GIFs small.

/// One of the palette's colours. The discriminant is the GIF palette index.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Colour {
    /// The background.
    Background = 0,
    /// Faint helper lines (the world bounds of a panel, a grid).
    Guide = 1,
    /// Fixed (static) bodies.
    Fixed = 2,
    /// Awake dynamic and kinematic bodies.
    Awake = 3,
    /// Sleeping dynamic bodies: the same shapes, drawn in a cool colour.
    Sleeping = 4,
    /// Body outlines.
    Outline = 5,
    /// Bullets (bodies with continuous collision).
    Bullet = 6,
    /// Contact points (the closest points of a touching pair).
    ContactPoint = 7,
    /// Contact normals.
    Normal = 8,
    /// Springs.
    Spring = 9,
    /// A rope at full length (taut).
    RopeTaut = 10,
    /// A rope shorter than its length (slack).
    RopeSlack = 11,
    /// Rays.
    Ray = 12,
    /// Ray hits.
    Hit = 13,
    /// Highlights: an aim line, a trail, a moving shape in a demo.
    Accent = 14,
    /// Text-like marks and frames.
    Ink = 15,
}

impl Colour {
    /// Every colour, in palette order (index = discriminant).
    pub const ALL: [Colour; 16] = [
        Colour::Background,
        Colour::Guide,
        Colour::Fixed,
        Colour::Awake,
        Colour::Sleeping,
        Colour::Outline,
        Colour::Bullet,
        Colour::ContactPoint,
        Colour::Normal,
        Colour::Spring,
        Colour::RopeTaut,
        Colour::RopeSlack,
        Colour::Ray,
        Colour::Hit,
        Colour::Accent,
        Colour::Ink,
    ];

    /// The colour as 8-bit sRGB `[r, g, b]`. All 16 are distinct (a test
    /// checks it), so a pixel's RGB names its colour exactly.
    #[must_use]
    pub const fn rgb(self) -> [u8; 3] {
        match self {
            Colour::Background => [250, 248, 240],
            Colour::Guide => [222, 219, 208],
            Colour::Fixed => [120, 124, 132],
            Colour::Awake => [236, 142, 52],
            Colour::Sleeping => [96, 150, 214],
            Colour::Outline => [52, 52, 60],
            Colour::Bullet => [204, 40, 60],
            Colour::ContactPoint => [214, 30, 160],
            Colour::Normal => [30, 150, 70],
            Colour::Spring => [140, 70, 200],
            Colour::RopeTaut => [110, 70, 30],
            Colour::RopeSlack => [190, 160, 110],
            Colour::Ray => [40, 170, 190],
            Colour::Hit => [230, 200, 20],
            Colour::Accent => [250, 90, 30],
            Colour::Ink => [20, 20, 24],
        }
    }

    /// The palette index (the discriminant).
    #[must_use]
    pub const fn index(self) -> u8 {
        self as u8
    }

    /// The palette colour nearest to `rgb` (squared distance in sRGB; ties go
    /// to the lower index). Exact for pixels drawn by this crate.
    #[must_use]
    pub fn nearest(rgb: [u8; 3]) -> Colour {
        let distance = |c: Colour| {
            let p = c.rgb();
            (0..3)
                .map(|i| {
                    let d = i32::from(p[i]) - i32::from(rgb[i]);
                    d * d
                })
                .sum::<i32>()
        };
        let mut best = Colour::Background;
        for c in Colour::ALL {
            if distance(c) < distance(best) {
                best = c;
            }
        }
        best
    }

    /// The GIF global colour table: 16 RGB triples in index order.
    #[must_use]
    pub fn gif_palette() -> Vec<u8> {
        Colour::ALL.iter().flat_map(|c| c.rgb()).collect()
    }
}
