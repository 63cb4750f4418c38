//! The raster evaluation against a direct one: every pixel centre tested against every
//! outline (the even-odd ray test) and the tree evaluated recursively.

use super::*;
use proptest::prelude::*;

/// The identity placement.
const ID: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// The square of side `w` from (x, y), counter-clockwise.
fn sq(x: f64, y: f64, w: f64) -> Vec<DVec2> {
    vec![
        DVec2::new(x, y),
        DVec2::new(x + w, y),
        DVec2::new(x + w, y + w),
        DVec2::new(x, y + w),
    ]
}

/// The same tree, as the test evaluates it.
#[derive(Clone, Debug)]
enum Tree {
    Shape(Vec<Vec<DVec2>>),
    Op(Op, Vec<Tree>),
}

impl Tree {
    fn push_to(&self, f: &mut Footprint) {
        match self {
            Tree::Shape(paths) => f.push_shape(paths.iter().map(|p| p.as_slice())),
            Tree::Op(op, c) => {
                c.iter().for_each(|c| c.push_to(f));
                f.push_op(*op, c.len());
            }
        }
    }

    /// Whether pixel-space point `q` is inside, the outlines mapped by `to_pixel`.
    fn holds(&self, q: DVec2, to_pixel: &dyn Fn(DVec2) -> DVec2) -> bool {
        match self {
            Tree::Shape(paths) => {
                let mut inside = false;
                for p in paths {
                    let p: Vec<DVec2> = p.iter().map(|&v| to_pixel(v)).collect();
                    for i in 0..p.len() {
                        let (a, b) = (p[i], p[(i + 1) % p.len()]);
                        let (a, b) = if a.y < b.y { (a, b) } else { (b, a) };
                        if a.y <= q.y && q.y < b.y {
                            let x = a.x + (q.y - a.y) * ((b.x - a.x) / (b.y - a.y));
                            inside ^= x <= q.x;
                        }
                    }
                }
                inside
            }
            Tree::Op(Op::Union, c) => c.iter().any(|c| c.holds(q, to_pixel)),
            Tree::Op(Op::Intersection, c) => c.iter().all(|c| c.holds(q, to_pixel)),
            Tree::Op(Op::Difference, c) => {
                c[0].holds(q, to_pixel) && !c[1..].iter().any(|c| c.holds(q, to_pixel))
            }
        }
    }
}

fn polygon() -> impl Strategy<Value = Vec<DVec2>> {
    prop_oneof![
        // A regular polygon (a circle of few or many fragments).
        (
            -12.0..12.0f64,
            -12.0..12.0f64,
            0.3..9.0f64,
            3usize..80,
            0.0..6.3f64
        )
            .prop_map(|(x, y, r, n, a)| (0..n)
                .map(|i| {
                    let t = a + i as f64 * std::f64::consts::TAU / n as f64;
                    DVec2::new(x + r * t.cos(), y + r * t.sin())
                })
                .collect()),
        // Any points: concave, self-crossing.
        prop::collection::vec((-12.0..12.0f64, -12.0..12.0f64), 3..9)
            .prop_map(|v| v.into_iter().map(|(x, y)| DVec2::new(x, y)).collect()),
        // An axis-aligned rectangle on whole numbers: edges through pixel centres.
        (-10i32..10, -10i32..10, 1i32..8, 1i32..8).prop_map(|(x, y, w, h)| {
            let (x, y, w, h) = (x as f64, y as f64, w as f64, h as f64);
            vec![
                DVec2::new(x, y),
                DVec2::new(x + w, y),
                DVec2::new(x + w, y + h),
                DVec2::new(x, y + h),
            ]
        }),
    ]
}

fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop::collection::vec(polygon(), 1..3).prop_map(Tree::Shape);
    leaf.prop_recursive(4, 24, 4, |inner| {
        (
            prop_oneof![
                Just(Op::Union),
                Just(Op::Intersection),
                Just(Op::Difference)
            ],
            prop::collection::vec(inner, 1..4),
        )
            .prop_map(|(op, c)| Tree::Op(op, c))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn the_raster_is_the_tree_at_every_pixel_centre(
        t in tree(),
        scale in prop_oneof![Just(1.0), 0.3..3.0f64],
        angle in prop_oneof![Just(0.0), -3.2..3.2f64],
        shift in (-20.0..20.0f64, -20.0..20.0f64),
        win in (0usize..20, 0usize..20, 1usize..40, 1usize..40),
    ) {
        let (s, c) = angle.sin_cos();
        let to_pixel = move |p: DVec2| {
            DVec2::new(c * p.x - s * p.y, s * p.x + c * p.y) * scale
                + DVec2::new(shift.0 + 20.0, shift.1 + 20.0)
        };
        let mut f = Footprint::new([0.0, 1.0], ID);
        t.push_to(&mut f);
        prop_assert!(f.is_complete());
        let win = Window { x0: win.0, y0: win.1, w: win.2, h: win.3 };
        let got = f.mask_in(to_pixel, win);
        for y in 0..win.h {
            for x in 0..win.w {
                let q = DVec2::new((win.x0 + x) as f64, (win.y0 + y) as f64);
                prop_assert_eq!(got[y * win.w + x], t.holds(q, &to_pixel), "pixel {:?}", q);
            }
        }
    }
}

#[test]
fn a_square_minus_a_hole_on_a_grid() {
    let mut f = Footprint::new([2.0, -1.0], ID);
    assert_eq!(f.z, [-1.0, 2.0]);
    f.push_shape([sq(0.5, 0.5, 4.0).as_slice()]);
    f.push_shape([sq(1.5, 1.5, 1.0).as_slice()]);
    f.push_op(Op::Difference, 2);
    assert!(f.is_complete());
    let m = f.mask_in(
        |p| p,
        Window {
            x0: 0,
            y0: 0,
            w: 6,
            h: 6,
        },
    );
    let rows: Vec<String> = m
        .chunks(6)
        .map(|r| r.iter().map(|&b| if b { '#' } else { '.' }).collect())
        .collect();
    // Centres 1..=4 in the square, centre (2, 2) in the hole.
    assert_eq!(
        rows,
        ["......", ".####.", ".#.##.", ".####.", ".####.", "......"]
    );
    assert_eq!(f.points(), 8);
    let (lo, hi) = f.bounds();
    assert_eq!(
        (lo, hi),
        (DVec3::new(0.5, 0.5, -1.0), DVec3::new(4.5, 4.5, 2.0))
    );
}

#[test]
fn incomplete_steps_are_found() {
    let mut f = Footprint::new([0.0, 1.0], ID);
    assert!(!f.is_complete());
    let tri = [DVec2::ZERO, DVec2::X, DVec2::Y];
    f.push_shape([tri.as_slice()]);
    f.push_shape([tri.as_slice()]);
    assert!(!f.is_complete());
    f.push_op(Op::Union, 3);
    assert!(!f.is_complete());
    assert!(keeps_z(&ID));
    let mut tilted = ID;
    tilted[0][2] = 0.5;
    assert!(!keeps_z(&tilted));
}

#[test]
fn the_box_follows_the_operations() {
    // A disc minus a groove reaching past it: the disc's box.
    let mut f = Footprint::new([0.0, 1.0], ID);
    f.push_shape([sq(0.0, 0.0, 4.0).as_slice()]);
    f.push_shape([sq(3.0, 3.0, 2.0).as_slice()]);
    f.push_op(Op::Difference, 2);
    assert_eq!(
        f.set_bounds(),
        (DVec3::new(0.0, 0.0, 0.0), DVec3::new(4.0, 4.0, 1.0))
    );
    assert_eq!(
        f.bounds(),
        (DVec3::new(0.0, 0.0, 0.0), DVec3::new(5.0, 5.0, 1.0))
    );
    // Intersected with a square apart from it: empty, and so is the box in the scene.
    f.push_shape([sq(10.0, 10.0, 1.0).as_slice()]);
    f.push_op(Op::Intersection, 2);
    let (lo, hi) = f.set_bounds();
    assert!(lo.x > hi.x);
    // United with another: that one's box.
    f.push_shape([sq(-2.0, 1.0, 1.0).as_slice()]);
    f.push_op(Op::Union, 2);
    assert_eq!(
        f.set_bounds(),
        (DVec3::new(-2.0, 1.0, 0.0), DVec3::new(-1.0, 2.0, 1.0))
    );
    // The scene's box counts every point, the cut-away and the empty too.
    assert_eq!(
        f.bounds(),
        (DVec3::new(-2.0, 0.0, 0.0), DVec3::new(11.0, 11.0, 1.0))
    );
}
