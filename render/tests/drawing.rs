//! Pictures show what the world holds, where it holds it: a body's colour
//! at its pixels, background around it, a sleeping body in its own colour,
//! contact points on both surfaces.

use clockwork2d::geometry::*;
use clockwork2d::prelude::*;
use clockwork2d_render::{
    Canvas, Colour, Layers, View, body_colour, contact_points, draw_contact, draw_ray, draw_world,
    view_of_world,
};

/// 10 pixels per unit, world origin at the centre of a 200×100 picture.
fn view() -> View {
    View {
        width: 200,
        height: 100,
        scale: 10.0,
        centre: (0.0, 0.0),
    }
}

#[test]
fn view_maps_world_to_pixels_with_y_up_and_back() {
    let view = view();
    assert_eq!(view.to_pixel((0.0, 0.0)), (100.0, 50.0));
    assert_eq!(view.to_pixel((1.0, 2.0)), (110.0, 30.0));
    assert_eq!(view.to_world(110.0, 30.0), (1.0, 2.0));
    // Fitting a 20×10 rectangle into 200×100 with no margin: 10 px/unit.
    let fit = View::fit((-10.0, -5.0), (10.0, 5.0), 200, 100, 0);
    assert_eq!(fit, view);
    // Far-off and NaN points stay finite (a frozen body must not panic).
    let (x, y) = view.to_pixel((1e30, f64::NAN));
    assert!(x.is_finite() && y.is_finite());
}

#[test]
fn a_body_is_drawn_at_its_place_and_nowhere_else() {
    let mut world = World::new(WorldSettings::default());
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(1.0))).position(vec2(3.0, 1.0)))
        .unwrap();
    let wall = world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(0.5, 2.0))).position(vec2(-5.0, 0.0)))
        .unwrap();
    let mut canvas = Canvas::new(view()).unwrap();
    draw_world(&mut canvas, &world, &Layers::default());
    // Ball centre (3, 1) -> pixel (130, 40); radius 10 px.
    assert_eq!(canvas.colour_at(130, 40), Some(Colour::Awake));
    assert_eq!(canvas.colour_at(136, 40), Some(Colour::Awake));
    assert_eq!(canvas.colour_at(130, 47), Some(Colour::Awake));
    // Just outside the circle (radius 10 px, outline 1 px): background.
    assert_eq!(canvas.colour_at(142, 40), Some(Colour::Background));
    assert_eq!(canvas.colour_at(130, 53), Some(Colour::Background));
    // Diagonal 9 px out on each axis is 12.7 px from the centre: outside.
    assert_eq!(canvas.colour_at(139, 49), Some(Colour::Background));
    // Wall: x in [-5.5, -4.5] -> pixels [45, 55], y in [-2, 2] -> [30, 70].
    assert_eq!(canvas.colour_at(50, 50), Some(Colour::Fixed));
    assert_eq!(canvas.colour_at(50, 32), Some(Colour::Fixed));
    assert_eq!(canvas.colour_at(43, 50), Some(Colour::Background));
    assert_eq!(canvas.colour_at(50, 73), Some(Colour::Background));
    assert_eq!(body_colour(world.body(wall).unwrap()), Colour::Fixed);
    assert_eq!(body_colour(world.body(ball).unwrap()), Colour::Awake);
    // Moving the ball moves its picture.
    world
        .apply(Command::SetPosition {
            body: ball,
            position: vec2(-2.0, -2.0),
        })
        .unwrap();
    let mut canvas = Canvas::new(view()).unwrap();
    draw_world(&mut canvas, &world, &Layers::default());
    assert_eq!(canvas.colour_at(130, 40), Some(Colour::Background));
    assert_eq!(canvas.colour_at_world((-2.0, -2.0)), Some(Colour::Awake));
}

#[test]
fn a_sleeping_body_is_drawn_differently_from_an_awake_one() {
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(5.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    let crate_box = world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(1.0, 1.0))).position(vec2(0.0, 1.0)))
        .unwrap();
    let centre_colour = |world: &World| {
        let mut canvas = Canvas::new(view_of_world(world, 120, 80).unwrap()).unwrap();
        draw_world(&mut canvas, world, &Layers::default());
        let p = world.body(crate_box).unwrap().position().to_f64();
        canvas.colour_at_world(p)
    };
    assert!(world.body(crate_box).unwrap().is_awake());
    assert_eq!(centre_colour(&world), Some(Colour::Awake));
    // Resting on the ground, it sleeps after `time_to_sleep` (0.5 s = 30
    // ticks) of rest; 120 ticks leave ample time to settle first.
    for _ in 0..120 {
        world.step();
    }
    assert!(
        !world.body(crate_box).unwrap().is_awake(),
        "the box should sleep"
    );
    assert_eq!(centre_colour(&world), Some(Colour::Sleeping));
    // Waking it brings the awake colour back.
    world.apply(Command::Wake(crate_box)).unwrap();
    assert_eq!(centre_colour(&world), Some(Colour::Awake));
}

#[test]
fn closest_points_lie_on_both_surfaces_for_every_shape_pair() {
    let circle = Shape::circle(fx(1.0));
    let square = Shape::aabb(vec2(1.0, 1.0));
    let close = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs() < 1e-6 && (p.1 - q.1).abs() < 1e-6;
    // Circles 3 apart on x: gap 1, points at x = 1 and x = 2.
    let c = contact_points(&circle, vec2(0.0, 0.0), &circle, vec2(3.0, 0.0));
    assert!(
        close(c.on_a, (1.0, 0.0)) && close(c.on_b, (2.0, 0.0)),
        "{c:?}"
    );
    // Overlapping circles: the points cross over (depth 0.5).
    let c = contact_points(&circle, vec2(0.0, 0.0), &circle, vec2(0.0, 1.5));
    assert!(
        close(c.on_a, (0.0, 1.0)) && close(c.on_b, (0.0, 0.5)),
        "{c:?}"
    );
    // Circle centre outside a box, off its corner: the box point is the
    // corner (1, 1); the circle's is on the diagonal at distance 1.
    let c = contact_points(&circle, vec2(3.0, 3.0), &square, vec2(0.0, 0.0));
    let d = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close(c.on_b, (1.0, 1.0)), "{c:?}");
    assert!(close(c.on_a, (3.0 - d, 3.0 - d)), "{c:?}");
    // Circle centre inside the box, nearer the right face: the box point is
    // on that face, the circle's point on its far (left) side.
    let c = contact_points(&circle, vec2(0.5, 0.2), &square, vec2(0.0, 0.0));
    assert!(close(c.on_b, (1.0, 0.2)), "{c:?}");
    assert!(close(c.on_a, (-0.5, 0.2)), "{c:?}");
    // Same pair, box first: the points swap roles.
    let c = contact_points(&square, vec2(0.0, 0.0), &circle, vec2(0.5, 0.2));
    assert!(
        close(c.on_a, (1.0, 0.2)) && close(c.on_b, (-0.5, 0.2)),
        "{c:?}"
    );
    // Boxes overlapping on x by 0.5, offset on y by 1: the points are on
    // the facing x faces, at the middle of the y overlap [0, 1].
    let c = contact_points(&square, vec2(0.0, 0.0), &square, vec2(1.5, 1.0));
    assert!(
        close(c.on_a, (1.0, 0.5)) && close(c.on_b, (0.5, 0.5)),
        "{c:?}"
    );
    // Boxes apart on both axes: nearest corners.
    let c = contact_points(&square, vec2(0.0, 0.0), &square, vec2(5.0, 2.5));
    assert!(
        close(c.on_a, (1.0, 1.0)) && close(c.on_b, (4.0, 1.5)),
        "{c:?}"
    );
}

#[test]
fn contacts_and_rays_are_drawn_where_they_are() {
    let circle = Shape::circle(fx(1.0));
    let points = contact_points(&circle, vec2(-2.0, 0.0), &circle, vec2(2.0, 0.0));
    let mut canvas = Canvas::new(view()).unwrap();
    draw_contact(&mut canvas, &points, 10.0);
    // Points at x = -1 and x = 1: pixels 90 and 110 on row 50.
    assert_eq!(canvas.colour_at(90, 50), Some(Colour::ContactPoint));
    assert_eq!(canvas.colour_at(110, 50), Some(Colour::ContactPoint));
    // The normal (+x) runs from (90, 50) to (100, 50): arrow pixels right of
    // the dot, none left of it.
    assert_eq!(canvas.colour_at(97, 50), Some(Colour::Normal));
    assert_eq!(canvas.colour_at(84, 50), Some(Colour::Background));

    let ray = Ray::new(vec2(-8.0, 2.0), vec2(1.0, 0.0), fx(20.0)).unwrap();
    let hit = ray_circle(&ray, &Circle::new(vec2(0.0, 2.0), fx(1.0))).unwrap();
    let mut canvas = Canvas::new(view()).unwrap();
    draw_ray(&mut canvas, &ray, Some(&hit), 8.0);
    // The ray along y = 2 (row 30) from x = -8 (pixel 20) to the hit at
    // x = -1 (pixel 90); nothing beyond the hit.
    assert_eq!(canvas.colour_at(50, 30), Some(Colour::Ray));
    assert_eq!(canvas.colour_at(90, 30), Some(Colour::Hit));
    assert_eq!(canvas.colour_at(120, 30), Some(Colour::Background));
}

#[test]
fn springs_and_ropes_are_drawn_between_their_anchors() {
    let mut world = World::new(WorldSettings::default());
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(0.0, -2.0)))
        .unwrap();
    world
        .add_constraint(Constraint::rope(
            Anchor::Point(vec2(0.0, 3.0)),
            Anchor::Body(ball),
            fx(5.0),
        ))
        .unwrap();
    let layers = Layers {
        bodies: false,
        ..Layers::default()
    };
    let mut canvas = Canvas::new(view()).unwrap();
    draw_world(&mut canvas, &world, &layers);
    // A taut rope (length 5 = distance): the straight segment x = 0 from
    // y = 3 (row 20) to y = -2 (row 70).
    assert_eq!(canvas.colour_at_world((0.0, 0.5)), Some(Colour::RopeTaut));
    // Slack (length 8): it sags below the chord, so the chord's midpoint
    // is empty... unless the sag is vertical. Use a horizontal chord.
    let mut world = World::new(WorldSettings::default());
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(4.0, 0.0)))
        .unwrap();
    world
        .add_constraint(Constraint::rope(
            Anchor::Point(vec2(-4.0, 0.0)),
            Anchor::Body(ball),
            fx(10.0),
        ))
        .unwrap();
    let mut canvas = Canvas::new(view()).unwrap();
    draw_world(&mut canvas, &world, &layers);
    assert_eq!(canvas.colour_at_world((0.0, 0.0)), Some(Colour::Background));
    // Sag h = sqrt(3·8·2/8) = sqrt(6) ≈ 2.449 below the chord's middle.
    assert_eq!(
        canvas.colour_at_world((0.0, -6.0_f64.sqrt())),
        Some(Colour::RopeSlack)
    );
    // A radial spring is a coil along the pole: spring-coloured pixels near
    // the pole's middle.
    let mut world = World::new(WorldSettings::default());
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(4.0, 0.0)))
        .unwrap();
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(vec2(-4.0, 0.0)),
            Anchor::Body(ball),
            fx(8.0),
            fx(10.0),
            fx(0.0),
        ))
        .unwrap();
    let mut canvas = Canvas::new(view()).unwrap();
    draw_world(&mut canvas, &world, &layers);
    let spring_pixels = (40..160)
        .flat_map(|x| (40..60).map(move |y| (x, y)))
        .filter(|&(x, y)| canvas.colour_at(x, y) == Some(Colour::Spring))
        .count();
    assert!(spring_pixels > 100, "{spring_pixels} spring pixels");
    assert_eq!(canvas.colour_at(100, 30), Some(Colour::Background));
}

#[test]
fn bad_sizes_are_refused_with_a_typed_error() {
    for (w, h) in [(0, 10), (10, 0), (5000, 10)] {
        let err = Canvas::new(View {
            width: w,
            height: h,
            ..view()
        })
        .err()
        .unwrap();
        assert!(
            matches!(err, clockwork2d_render::RenderError::BadSize { .. }),
            "{err}"
        );
    }
    let empty = World::new(WorldSettings::default());
    assert!(matches!(
        view_of_world(&empty, 10, 10),
        Err(clockwork2d_render::RenderError::EmptyWorld)
    ));
}

#[test]
fn contacts_are_drawn_between_visible_bodies_only() {
    // Two unit boxes resting on each other, after a step (so they touch).
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(5.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, 0.5)))
        .unwrap();
    world.step();
    assert_eq!(world.touching_pairs().count(), 1);
    let count = |scale: f64| {
        let mut canvas = Canvas::new(View { scale, ..view() }).unwrap();
        draw_world(&mut canvas, &world, &Layers::default());
        (0..200)
            .flat_map(|x| (0..100).map(move |y| (x, y)))
            .filter(|&(x, y)| canvas.colour_at(x, y) == Some(Colour::ContactPoint))
            .count()
    };
    // 10 px/unit: half-size 5 px, contact drawn; 6 px/unit: 3 px, not.
    assert!(count(10.0) > 0);
    assert_eq!(count(6.0), 0);
}
