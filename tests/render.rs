//! The fast disc renderer against the oracle loop, and the camera/intersection conventions of
//! docs/spec.md seen through whole frames: non-square crops, ties, cameras inside spheres, spheres
//! behind the camera centre, determinism.

use std::path::Path;

use glam::{DVec3, Vec3};
use raytracer::oracle::ray_loop::render_reference;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{Frame, NO_HIT, View, render};
use raytracer::scene::{Material, OrthographicCamera, Scene, Sphere, load_scene};

fn course_scene(number: u32) -> Scene {
    load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/scene1_0{number}.txt")))
        .unwrap()
}

fn view_of(scene: &Scene, width_px: u32, height_px: u32) -> View {
    View::of_camera(
        &scene.camera,
        width_px,
        height_px,
        DepthRange::new(0.0, 1.0),
    )
}

/// A small deterministic generator (SplitMix64), so the random scenes are the same every run.
struct SplitMix(u64);

impl SplitMix {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn random_scene(seed: u64, sphere_count: usize) -> Scene {
    let mut rng = SplitMix(seed);
    let materials = (0..4)
        .map(|i| Material {
            diffuse_colour: Vec3::new(i as f32 / 4.0, 0.5, 1.0 - i as f32 / 4.0),
        })
        .collect();
    let spheres = (0..sphere_count)
        .map(|i| Sphere {
            center_world: DVec3::new(
                rng.uniform(-3.0, 3.0),
                rng.uniform(-3.0, 3.0),
                rng.uniform(-3.0, 3.0),
            ),
            radius_world: rng.uniform(0.05, 1.0),
            material: Some((i % 4) as u32),
        })
        .collect();
    let direction = DVec3::new(
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, -0.2),
    );
    Scene {
        camera: OrthographicCamera {
            center_world: -8.0 * direction,
            direction_world: direction,
            up_world: DVec3::new(rng.uniform(-0.5, 0.5), 1.0, rng.uniform(-0.5, 0.5)),
            size_world: 8.0,
        },
        background: Vec3::splat(0.25),
        materials,
        spheres,
    }
}

/// Asserts that the fast frame and the oracle frame agree: the same sphere wherever the pixel is
/// not within rounding of a silhouette or a tie, and t within `1e-12 · scale` where they agree.
fn assert_frames_agree(scene: &Scene, view: &View, fast: &Frame, oracle: &Frame) -> usize {
    assert_colours_follow_spheres(scene, fast);
    let basis = view.validate().unwrap();
    let grid = view.grid();
    let scale = scene.bounds().map_or(1.0, |b| b.diagonal()) + view.size_world;
    let mut silhouette_pixels = 0;
    for y_up in 0..view.height_px {
        for x in 0..view.width_px {
            let index = fast.index(x, y_up);
            let (u, v) = (
                grid.u_of_column(f64::from(x)),
                grid.v_of_row(f64::from(y_up)),
            );
            if fast.sphere[index] == oracle.sphere[index] {
                let (a, b) = (fast.t[index], oracle.t[index]);
                assert!(
                    a == b || (a - b).abs() <= 1e-12 * scale,
                    "pixel ({x}, {y_up}): t {a} vs {b}"
                );
                continue;
            }
            // Disagreement is allowed only on a silhouette (|d² − r²| at rounding level) or a tie.
            let near_silhouette = [fast.sphere[index], oracle.sphere[index]]
                .into_iter()
                .filter(|&s| s != NO_HIT)
                .any(|s| {
                    let sphere = &scene.spheres[s as usize];
                    let c = basis.to_camera(sphere.center_world - view.center_world);
                    let d2 = (u - c.x).powi(2) + (v - c.y).powi(2);
                    let r2 = sphere.radius_world.powi(2);
                    (d2 - r2).abs() <= 1e-12 * scale * scale
                });
            let tie = (fast.t[index] - oracle.t[index]).abs() <= 1e-12 * scale;
            assert!(
                near_silhouette || tie,
                "pixel ({x}, {y_up}): sphere {} vs {}",
                fast.sphere[index],
                oracle.sphere[index]
            );
            silhouette_pixels += 1;
        }
    }
    silhouette_pixels
}

/// Every pixel of `frame` has the colour of the sphere it shows (its material's diffuse colour,
/// white without one) or the background, each channel quantised as `floor(c·255)` within
/// [0, 255] — worked out here from the scene, not by the renderer's shading.
fn assert_colours_follow_spheres(scene: &Scene, frame: &Frame) {
    assert_eq!(frame.colour.len(), frame.sphere.len());
    for (index, (&rgb, &sphere)) in frame.colour.iter().zip(&frame.sphere).enumerate() {
        let colour = if sphere == NO_HIT {
            scene.background
        } else {
            scene.spheres[sphere as usize]
                .material
                .map_or(Vec3::ONE, |m| scene.materials[m as usize].diffuse_colour)
        };
        let expected = colour
            .to_array()
            .map(|c| (c * 255.0).clamp(0.0, 255.0) as u8);
        assert_eq!(rgb, expected, "pixel {index}: colour of sphere {sphere}");
    }
}

#[test]
fn fast_path_matches_the_oracle_on_the_course_scenes() {
    for number in 1..=7 {
        let scene = course_scene(number);
        for (width, height) in [(200, 200), (123, 77), (64, 301)] {
            let view = view_of(&scene, width, height);
            let fast = render(&scene, &view).unwrap();
            let oracle = render_reference(&scene, &view).unwrap();
            assert_eq!(
                assert_frames_agree(&scene, &view, &fast, &oracle),
                0,
                "scene1_0{number} {width}×{height}"
            );
            assert_eq!(fast.colour, oracle.colour, "scene1_0{number}");
        }
    }
}

#[test]
fn fast_path_matches_the_oracle_on_random_scenes() {
    let mut silhouette_pixels = 0;
    for seed in 0..40 {
        let scene = random_scene(seed, 1 + (seed as usize * 7) % 60);
        let view = view_of(&scene, 96, 80);
        let fast = render(&scene, &view).unwrap();
        let oracle = render_reference(&scene, &view).unwrap();
        silhouette_pixels += assert_frames_agree(&scene, &view, &fast, &oracle);
    }
    // Rounding may flip a pixel that sits on a silhouette, but that must stay rare.
    assert!(
        silhouette_pixels <= 5,
        "{silhouette_pixels} silhouette pixels differ"
    );
}

#[test]
fn binned_path_matches_brute_force_on_large_generated_scenes() {
    // Beyond 16,384 spheres the discs are binned in chunks on several threads; every band's list
    // must still hold every disc in file order. 40,000 spheres of ~1-pixel discs (many ties of
    // nearly equal depth) and 3,000 big overlapping ones, against the brute-force loop.
    for (count, side_px) in [(40_000usize, 160u32), (3_000, 120)] {
        let scene = raytracer::oracle::random_scene(11, count);
        let view = view_of(&scene, side_px, side_px - 17);
        let fast = render(&scene, &view).unwrap();
        let oracle = render_reference(&scene, &view).unwrap();
        let silhouette_pixels = assert_frames_agree(&scene, &view, &fast, &oracle);
        assert!(
            silhouette_pixels <= 3,
            "{count} spheres: {silhouette_pixels} silhouette pixels differ"
        );
        assert!(fast.sphere.iter().filter(|&&s| s != NO_HIT).count() > 1000);
    }
}

#[test]
fn non_square_images_show_the_middle_of_the_square_screen() {
    let scene = course_scene(2);
    let square = render(&scene, &view_of(&scene, 200, 200)).unwrap();
    let wide = render(&scene, &view_of(&scene, 200, 100)).unwrap();
    let tall = render(&scene, &view_of(&scene, 100, 200)).unwrap();
    for y_up in 0..100 {
        for x in 0..200 {
            let wide_index = wide.index(x, y_up);
            let square_index = square.index(x, y_up + 50);
            assert_eq!(wide.sphere[wide_index], square.sphere[square_index]);
            assert_eq!(wide.t[wide_index], square.t[square_index]);
            let tall_index = tall.index(y_up, x);
            let square_index = square.index(y_up + 50, x);
            assert_eq!(tall.sphere[tall_index], square.sphere[square_index]);
            assert_eq!(tall.t[tall_index], square.t[square_index]);
        }
    }
    // The crop really is the middle: the red sphere (index 0) sits at the screen's centre.
    assert_eq!(wide.sphere[wide.index(100, 50)], 0);
    assert_eq!(tall.sphere[tall.index(50, 100)], 0);
}

fn one_sphere_scene(center: [f64; 3], spheres: &[([f64; 3], f64, u32)]) -> Scene {
    Scene {
        camera: OrthographicCamera {
            center_world: DVec3::from(center),
            direction_world: DVec3::NEG_Z,
            up_world: DVec3::Y,
            size_world: 4.0,
        },
        background: Vec3::ZERO,
        materials: vec![
            Material {
                diffuse_colour: Vec3::X,
            },
            Material {
                diffuse_colour: Vec3::Y,
            },
        ],
        spheres: spheres
            .iter()
            .map(|&(center, radius, material)| Sphere {
                center_world: DVec3::from(center),
                radius_world: radius,
                material: Some(material),
            })
            .collect(),
    }
}

#[test]
fn ties_go_to_the_sphere_first_in_the_file() {
    for order in [[0, 1], [1, 0]] {
        let scene = one_sphere_scene(
            [0.0, 0.0, 10.0],
            &[
                ([0.0, 0.0, 0.0], 1.0, order[0]),
                ([0.0, 0.0, 0.0], 1.0, order[1]),
            ],
        );
        let view = view_of(&scene, 20, 20);
        for frame in [
            render(&scene, &view).unwrap(),
            render_reference(&scene, &view).unwrap(),
        ] {
            let centre = frame.index(10, 10);
            assert_eq!(frame.sphere[centre], 0);
            let expected = scene.materials[order[0] as usize].diffuse_colour;
            assert_eq!(
                frame.colour[centre],
                expected.to_array().map(|c| (c * 255.0) as u8)
            );
        }
    }
}

#[test]
fn camera_inside_a_sphere_and_spheres_behind_it_are_seen() {
    // Camera centre inside sphere 0; sphere 1 entirely behind the screen plane.
    let scene = one_sphere_scene(
        [0.0, 0.0, 0.0],
        &[([-1.0, 0.0, 0.0], 1.5, 0), ([1.2, 0.0, 5.0], 0.5, 1)],
    );
    let view = view_of(&scene, 40, 40);
    let frame = render(&scene, &view).unwrap();
    let grid = view.grid();
    let column_of = |u: f64| ((u / grid.pixel_size_world) + 19.5).round() as u32;
    let inside = frame.index(column_of(-1.0), 20);
    assert_eq!(frame.sphere[inside], 0);
    assert!(
        frame.t[inside] < 0.0,
        "front surface behind the camera centre: negative t"
    );
    let behind = frame.index(column_of(1.2), 20);
    assert_eq!(frame.sphere[behind], 1);
    assert!(frame.t[behind] < -4.0);
}

#[test]
fn tangent_pixel_hits_and_the_next_one_misses() {
    // 32 px over size 4: pixel centres at odd multiples of 0.0625, all exact in binary. The
    // sphere's centre sits on row 16's centre line and its radius reaches exactly the centres of
    // columns 11 and 20: the discriminant there is exactly 0.
    let scene = one_sphere_scene([0.0, 0.0, 10.0], &[([0.0, 0.0625, 0.0], 0.5625, 0)]);
    let view = view_of(&scene, 32, 32);
    for frame in [
        render(&scene, &view).unwrap(),
        render_reference(&scene, &view).unwrap(),
    ] {
        for x in [11, 20] {
            let tangent = frame.index(x, 16);
            assert_eq!(frame.sphere[tangent], 0, "column {x}");
            assert_eq!(frame.t[tangent], 10.0);
        }
        assert_eq!(frame.sphere[frame.index(10, 16)], NO_HIT);
        assert_eq!(frame.sphere[frame.index(21, 16)], NO_HIT);
    }
}

#[test]
fn rendering_is_deterministic_across_thread_counts() {
    // 200,000 random spheres are binned in chunks sized by the thread count; 200,000 dense ones
    // are drawn in passes, their discs sorted by depth in one group per thread.
    let scenes = [
        (
            "200 random",
            raytracer::oracle::random_scene(7, 200),
            (257, 129),
        ),
        (
            "200,000 random",
            raytracer::oracle::random_scene(7, 200_000),
            (160, 96),
        ),
        (
            "200,000 dense",
            raytracer::oracle::dense_scene(7, 200_000),
            (160, 96),
        ),
    ];
    for (name, scene, size) in scenes {
        let view = view_of(&scene, size.0, size.1);
        let with_threads = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| render(&scene, &view).unwrap())
        };
        let one = with_threads(1);
        for threads in [2, 5, 16] {
            let differ = format!("{name}: 1 and {threads} threads differ");
            assert!(one == with_threads(threads), "{differ}");
        }
    }
}

#[test]
fn invalid_views_are_errors_not_panics() {
    let scene = course_scene(1);
    let good = view_of(&scene, 10, 10);
    let cases = [
        View {
            size_world: 0.0,
            ..good
        },
        View {
            size_world: f64::NAN,
            ..good
        },
        View {
            width_px: 0,
            ..good
        },
        View {
            direction_world: DVec3::ZERO,
            ..good
        },
        View {
            up_world: DVec3::new(0.0, 0.0, 2.0),
            ..good
        },
        View {
            center_world: DVec3::new(f64::INFINITY, 0.0, 0.0),
            ..good
        },
        View {
            depth_range: DepthRange::new(f64::NAN, 1.0),
            ..good
        },
    ];
    for view in cases {
        assert!(render(&scene, &view).is_err(), "{view:?}");
    }
}

#[test]
fn culled_front_to_back_path_matches_brute_force_and_keeps_ties_in_file_order() {
    // The dense scene's generator (60,000 spheres: every pixel covered about ten times over, so
    // most discs are culled as hidden) with a file that ends with exact copies of every tenth
    // sphere: the copies tie with their originals everywhere, and the original (first in the
    // file) must win every tie although discs are drawn front to back, not in file order.
    let mut scene = raytracer::oracle::dense_scene(3, 60_000);
    let originals = scene.spheres.len();
    let copies: Vec<_> = scene.spheres.iter().step_by(10).cloned().collect();
    scene.spheres.extend(copies);
    // Zoomed in on the middle, so the discs are several pixels wide.
    let mut view = view_of(&scene, 120, 100);
    view.size_world = 30.0;
    let fast = render(&scene, &view).unwrap();
    let oracle = render_reference(&scene, &view).unwrap();
    let silhouette_pixels = assert_frames_agree(&scene, &view, &fast, &oracle);
    assert!(silhouette_pixels <= 3, "{silhouette_pixels} pixels differ");
    let copies_seen = fast
        .sphere
        .iter()
        .filter(|&&s| s != NO_HIT && s as usize >= originals)
        .count();
    assert_eq!(copies_seen, 0, "a copy won a tie with its original");
    // Every pixel is covered (the comparison compared something).
    assert!(fast.sphere.iter().all(|&s| s != NO_HIT));
}

#[test]
fn a_far_sphere_seen_only_beside_a_covered_half_is_drawn() {
    // Dense frames are drawn in passes, front to back, and a later pass drops discs hidden behind
    // what the earlier ones drew. Here, one pixel per world unit: a wall of near spheres (the
    // first pass), over seven deep, covers one half of the image exactly, up to the middle column
    // but one; a far sphere (a later pass) straddles the middle, behind the wall on one side and in
    // the open on the other. Only that side of it can show, and it must. Its centre lies behind
    // the wall, so everything drawn around the centre is nearer: only its size says it reaches
    // the open side.
    let mut spheres = Vec::new();
    for column in 0..30 {
        for row in 0..64 {
            let x = -4.6 - 2.0 * f64::from(column);
            let y = -63.0 + 2.0 * f64::from(row);
            spheres.push(([x, y, 0.0], 4.5, 0));
        }
    }
    let far = spheres.len();
    spheres.push(([-20.0, 0.0, -50.0], 40.0, 1));
    let mut scene = one_sphere_scene([0.0, 0.0, 10.0], &spheres);
    scene.camera.size_world = 128.0;
    let view = view_of(&scene, 128, 128);
    let fast = render(&scene, &view).unwrap();
    let oracle = render_reference(&scene, &view).unwrap();
    let far_pixels = |frame: &Frame| frame.sphere.iter().filter(|&&s| s as usize == far).count();
    // The segment of the far disc (radius 40) beyond a chord 20 from its centre: about 983
    // pixels.
    assert!(
        (900..=1000).contains(&far_pixels(&oracle)),
        "{}",
        far_pixels(&oracle)
    );
    assert_eq!(far_pixels(&fast), far_pixels(&oracle));
    assert_frames_agree(&scene, &view, &fast, &oracle);
}

#[test]
fn a_later_pass_shows_where_the_earlier_one_curves_away() {
    // Culling compares a disc's nearest t with the farthest t drawn around it, not the nearest:
    // four big spheres (each four times over, so the frame is dense) cover the whole image and
    // are drawn first; small spheres behind their fronts come in a later pass, and those in the
    // middle, where the big ones curve away, are nearer than them there and must show.
    let mut spheres = Vec::new();
    for _copy in 0..4 {
        for (x, y) in [(-32.0, -32.0), (32.0, -32.0), (-32.0, 32.0), (32.0, 32.0)] {
            spheres.push(([x, y, 0.0], 48.0, 0));
        }
    }
    let first_small = spheres.len();
    for row in 0..9 {
        for column in 0..9 {
            let (x, y) = (
                -64.0 + 16.0 * f64::from(column),
                -64.0 + 16.0 * f64::from(row),
            );
            spheres.push(([x, y, 20.0], 3.0, 1));
        }
    }
    let mut scene = one_sphere_scene([0.0, 0.0, 200.0], &spheres);
    scene.camera.size_world = 128.0;
    let view = view_of(&scene, 128, 128);
    let fast = render(&scene, &view).unwrap();
    let oracle = render_reference(&scene, &view).unwrap();
    let small_pixels = |frame: &Frame| {
        frame
            .sphere
            .iter()
            .filter(|&&s| s != NO_HIT && s as usize >= first_small)
            .count()
    };
    assert!(small_pixels(&oracle) >= 64, "{}", small_pixels(&oracle));
    assert_eq!(small_pixels(&fast), small_pixels(&oracle));
    assert_frames_agree(&scene, &view, &fast, &oracle);
}
