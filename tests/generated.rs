//! The diagnosis on generated programs: a student's ray caster written here with knobs
//! (`examples/support/student.rs`: its own camera, one world-space ray per pixel, the textbook
//! quadratic; no code shared with the diagnosis's model), each program with one to three
//! behaviours of non-round values drawn from a seeded sequence. No statement may be one the
//! program's behaviours do not make true, and 99% of the differing cases must be explained to
//! within 1% of their pixels. `docs/diagnosis.md` reports the first 300 such programs.

#[path = "../examples/support/course.rs"]
mod course;
#[path = "../examples/support/judge.rs"]
mod judge;
#[path = "../examples/support/generated.rs"]
mod programs;
#[path = "../examples/support/student.rs"]
mod student;

use raytracer::compare::Difference;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::{View, render};

use judge::Verdict;

/// Cases the README's test command diagnoses; `cargo xtask corpus` (which CI runs) diagnoses
/// [`CASES`], and the report 300, in a release build.
const SAMPLED_CASES: u64 = 20;

/// Cases CI diagnoses (the ignored tests below).
const CASES: u64 = 60;

/// Cases of the report's 300 the diagnosis once read wrongly or left unexplained, diagnosed too:
/// a tilt standing in for a sample a twentieth of a pixel off (298), a square block read with a
/// tilt (226), a flip of a scene that looks the same turned a quarter with its tilt not fitted
/// again (270), spheres around the ray origins refused, fitted as a skewed map (280), a lone
/// sphere's far root (170).
const ONCE_MISREAD: [u64; 5] = [170, 226, 270, 280, 298];

#[test]
fn the_student_caster_with_no_knob_turned_draws_the_exact_images() {
    for case in programs::cases(21) {
        let program = student::Program::course();
        let (colour, depth) = student::render(
            &program,
            &case.scene,
            case.width,
            case.height,
            case.range.0,
            case.range.1,
        );
        let view = View::of_camera(
            &case.scene.camera,
            case.width,
            case.height,
            DepthRange::new(case.range.0, case.range.1),
        );
        let frame = render(&case.scene, &view).unwrap();
        let colour = Difference::of(&colour, &frame.colour_image());
        let depth = Difference::of(&depth, &frame.depth_image(view.depth_range));
        assert!(
            colour.colour_matches(),
            "seed {}: {} px",
            case.seed,
            colour.pixels_differing()
        );
        assert!(
            depth.depth_matches(),
            "seed {}: {} px",
            case.seed,
            depth.pixels_differing()
        );
    }
}

#[test]
fn generated_programs_get_no_false_statement_and_are_explained() {
    programs_get_no_false_statement_and_are_explained(SAMPLED_CASES);
}

#[test]
#[ignore = "60 programs: `cargo xtask corpus` runs it (CI does)"]
fn sixty_generated_programs_get_no_false_statement_and_are_explained() {
    programs_get_no_false_statement_and_are_explained(CASES);
}

/// The first `count` generated programs and those once misread, each diagnosed from both images.
fn programs_get_no_false_statement_and_are_explained(count: u64) {
    let mut wrong = Vec::new();
    let (mut differing, mut explained) = (0, 0);
    let last_misread = ONCE_MISREAD.iter().copied().max().unwrap_or(0);
    let cases = programs::cases(count.max(last_misread + 1))
        .into_iter()
        .filter(|case| case.seed < count || ONCE_MISREAD.contains(&case.seed));
    for case in cases {
        let (verdict, said, left) = case.diagnose();
        match verdict {
            Verdict::Wrong => wrong.push(format!(
                "seed {}: {:?} said {said:?}, {left} px left",
                case.seed,
                case.program.truth()
            )),
            Verdict::Match => {}
            Verdict::Explained => {
                differing += 1;
                explained += 1;
            }
            Verdict::Partial => differing += 1,
        }
    }
    assert_eq!(
        wrong,
        Vec::<String>::new(),
        "statements the programs do not make true"
    );
    // Two in three programs at least draw a picture that differs (40 of the first 60).
    assert!(3 * differing >= 2 * count, "{differing} of {count}");
    assert!(
        explained * 100 >= 99 * differing,
        "{explained} of {differing} differing cases explained to 1% of their pixels"
    );
}

/// The answer for `program`'s two images of the course scene `name` at 200×200, the program
/// drawing depth over `theirs` and the diagnosis given `given`.
fn answer_of(
    name: &str,
    program: &student::Program,
    theirs: (f64, f64),
    given: (f64, f64),
) -> raytracer::compare::Diagnosis {
    use raytracer::compare::{Theirs, diagnose};
    let scene = raytracer::scene::load_scene(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.txt")),
    )
    .unwrap();
    let (colour, depth) = student::render(program, &scene, 200, 200, theirs.0, theirs.1);
    let view = View::of_camera(&scene.camera, 200, 200, DepthRange::new(given.0, given.1));
    diagnose(
        &scene,
        &view,
        Theirs {
            colour: Some(&colour),
            depth: Some(&depth),
        },
    )
}

/// The diagnosis of `program`'s images (as [`answer_of`]): the statements said (with values), and
/// the pixels left unexplained.
fn diagnosed(
    name: &str,
    program: &student::Program,
    theirs: (f64, f64),
    given: (f64, f64),
) -> (Vec<String>, usize) {
    let answer = answer_of(name, program, theirs, given);
    let said = answer
        .stated()
        .iter()
        .map(raytracer::compare::Deviation::name_and_values)
        .collect();
    (said, answer.unexplained_pixels())
}

/// Depth drawn from the hit point's |z| (a knob the seeded draw never turns): on scene1_04, whose
/// camera looks along a diagonal, |z| is neither t nor another coordinate, and the answer must
/// say it, with no other statement.
#[test]
fn depth_drawn_from_the_hit_points_z_is_said_as_such() {
    let program = student::Program {
        depth: student::DepthRule::AbsZ,
        ..student::Program::course()
    };
    let (said, left) = diagnosed("scene1_04", &program, (0.0, 2.0), (0.0, 2.0));
    assert_eq!(said, ["depth-quantity |z|"]);
    assert_eq!(left, 0, "{said:?}");
}

/// Depth over a range of the program's own (not the one given) and not clamped: the wrap must be
/// fitted beside the range, where no named point (the given range, reversed or scaled) reaches.
#[test]
fn an_own_depth_range_that_wraps_is_said_with_its_range() {
    let program = student::Program {
        outside: student::OutsideRule::Wrap,
        ..student::Program::course()
    };
    let (said, left) = diagnosed("scene1_05", &program, (15.5, 18.0), (14.5, 19.5));
    assert!(said.iter().any(|s| s == "depth-no-clamp"), "{said:?}");
    assert!(
        said.iter().any(|s| s.starts_with("depth-range")),
        "{said:?}"
    );
    assert_eq!(left, 0, "{said:?}");
}

/// A tmin of any value with the far root tried where the near one is refused (−1 and −0.81 on
/// scene1_07, whose camera sits among the spheres): found with its value, as `tmin`, and nothing
/// else said.
#[test]
fn a_tmin_of_any_value_with_the_far_root_is_found_with_its_value() {
    for tmin in [-1.0, -0.81] {
        let program = student::Program {
            tmin,
            ..student::Program::course()
        };
        let (said, left) = diagnosed("scene1_07", &program, (-2.0, 2.0), (-2.0, 2.0));
        assert_eq!(said.len(), 1, "{tmin}: {said:?}");
        let value: f64 = said[0]
            .strip_prefix("tmin ")
            .unwrap_or_else(|| panic!("{tmin}: {said:?}"))
            .parse()
            .unwrap();
        assert!((value - tmin).abs() <= 0.05, "{tmin}: {said:?}");
        assert_eq!(left, 0, "{tmin}: {said:?}");
    }
}

/// Several samples per pixel on a fixed grid over the screen (1024 a side, whatever the image's
/// size), the last or the first sample that hits setting the pixel: found with its size and
/// order, every sphere drawn larger.
#[test]
fn a_grid_of_samples_where_the_last_hit_wins_is_found() {
    for (side, last) in [(1024, true), (600, false)] {
        let program = student::Program {
            grid: Some((side, last)),
            ..student::Program::course()
        };
        let (said, left) = diagnosed("scene1_02", &program, (8.0, 12.0), (8.0, 12.0));
        let order = if last { "last" } else { "first" };
        assert_eq!(said, [format!("sample-grid {side} {order}")], "{said:?}");
        assert!(left <= 400, "{left} px left: {said:?}");
    }
}

/// Each image alone (the colour image; the depth image with its range), as a student compares one
/// file: no statement false, and at least 99% of the differing images of each kind explained (of
/// the sixty cases, about forty-five differ in each kind, so every one must be); docs/diagnosis.md
/// reports all 300 cases.
#[test]
fn single_images_of_generated_programs_get_no_false_statement() {
    single_images_get_no_false_statement(SAMPLED_CASES);
}

#[test]
#[ignore = "60 programs: `cargo xtask corpus` runs it (CI does)"]
fn single_images_of_sixty_generated_programs_get_no_false_statement() {
    single_images_get_no_false_statement(CASES);
}

/// The first `count` generated programs, each diagnosed from its colour image and its depth image
/// alone.
fn single_images_get_no_false_statement(count: u64) {
    use programs::Given;
    use rayon::prelude::*;
    let cases = programs::cases(count);
    let answers: Vec<(u64, &str, Verdict, Vec<String>)> = cases
        .par_iter()
        .flat_map(|case| {
            [(Given::Colour, "colour"), (Given::Depth, "depth")]
                .into_iter()
                .map(|(given, name)| {
                    let (verdict, said, _) = case.diagnose_given(given);
                    (case.seed, name, verdict, said)
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let wrong: Vec<String> = answers
        .iter()
        .filter(|a| a.2 == Verdict::Wrong)
        .map(|(seed, name, _, said)| format!("seed {seed} {name}: {said:?}"))
        .collect();
    assert_eq!(
        wrong,
        Vec::<String>::new(),
        "false statements on single images"
    );
    for (name, share) in [("colour", 0.99), ("depth", 0.99)] {
        let of_kind: Vec<&Verdict> = answers
            .iter()
            .filter(|a| a.1 == name && a.2 != Verdict::Match)
            .map(|a| &a.2)
            .collect();
        let explained = of_kind
            .iter()
            .filter(|v| ***v == Verdict::Explained)
            .count();
        assert!(
            explained as f64 >= share * of_kind.len() as f64,
            "{name} alone: {explained} of {} explained",
            of_kind.len()
        );
    }
}

/// A non-square image whose rows are measured from an edge with one normaliser (the crop strip:
/// cases 118, 140 and 254 of the report, each image alone) is said as a scale and where rays
/// start, nothing else: the fit once stopped on a matrix a hair sheared and said it (`axes`, with
/// or without a tie), which such a program does not do.
#[test]
fn a_strip_measured_from_an_edge_is_said_as_a_scale_not_a_shear() {
    use programs::Given;
    let cases = programs::cases(255);
    for (seed, given) in [
        (118, Given::Depth),
        (140, Given::Colour),
        (254, Given::Colour),
    ] {
        let (verdict, said, _) = cases[seed].diagnose_given(given);
        assert_eq!(verdict, Verdict::Explained, "seed {seed}: {said:?}");
        assert!(
            said.iter()
                .any(|s| s.starts_with("axes-scaled ") || s.starts_with("zoom ")),
            "seed {seed}: {said:?}"
        );
        assert!(
            !said
                .iter()
                .any(|s| s.starts_with("axes ") || s.starts_with("one of:")),
            "seed {seed}: {said:?}"
        );
    }
}

/// A depth image alone of one sphere drawn with a tilt (case 135 of the report: scales 1.007 and
/// 0.863, a ramp of t across the screen) is said as the scales and the ramp: the fit once kept a
/// sample 0.04 pixels off the pixel's centre beside them (`sample-offset 0.5 0.46`), which draws
/// their pixels no better and which their program does not do.
#[test]
fn a_tilt_on_one_sphere_is_not_said_with_a_sample_a_hair_off() {
    let case = &programs::cases(136)[135];
    let (verdict, said, _) = case.diagnose_given(programs::Given::Depth);
    assert_eq!(verdict, Verdict::Explained, "{said:?}");
    assert!(said.iter().any(|s| s.starts_with("t-ramp ")), "{said:?}");
    assert!(
        !said.iter().any(|s| s.starts_with("sample-offset ")),
        "{said:?}"
    );
}

/// A depth image alone of a zoomed picture is said as the zoom: the silhouettes' fit from the
/// greys once settled on a longer story (case 61 of the report, scene1_03 at 90×140 zoomed
/// 0.907: the map turned a quarter with the far root, the depth reversed and no depth test; case
/// 133, one sphere at 90×140 scaled 0.897 by 1.295: nothing said), each leaving thousands of
/// pixels; the boxes around what is drawn give the map.
#[test]
fn a_zoomed_depth_image_alone_is_said_as_the_zoom() {
    let cases = programs::cases(134);
    for (seed, scale) in [(61, [0.907, 0.907]), (133, [0.897, 1.295])] {
        let (verdict, said, left) = cases[seed].diagnose_given(programs::Given::Depth);
        assert_eq!(verdict, Verdict::Explained, "seed {seed}: {said:?}");
        assert_eq!(left, 0, "seed {seed}: {said:?}");
        let values: Vec<f64> = said
            .iter()
            .filter(|s| s.starts_with("zoom ") || s.starts_with("axes-scaled "))
            .flat_map(|s| s.split(' ').skip(1).map(|v| v.parse::<f64>().unwrap()))
            .collect();
        let values = if values.len() == 1 {
            vec![values[0]; 2]
        } else {
            values
        };
        assert_eq!(values.len(), 2, "seed {seed}: {said:?}");
        for (value, truth) in values.iter().zip(scale) {
            assert!((value - truth).abs() < 0.002, "seed {seed}: {said:?}");
        }
    }
}

/// A depth image alone that the fit from the plain starts leaves unexplained is fitted again from
/// each named point of the map: a mirrored picture of a program with a tmin of zero (case 85 of
/// the report, scene1_07: two discs where the course draws three), one upside down, stretched and
/// zoomed (case 267), and one drawn in a zoomed square block (case 46) each left thousands of
/// pixels and no statement; each is said, with the mirror, the flip and the scales named.
#[test]
fn a_flipped_depth_image_alone_is_fitted_again_from_the_named_points() {
    let cases = programs::cases(268);
    for (seed, named) in [
        (85, &["mirrored", "tmin-zero"][..]),
        (267, &["flipped-vertically", "stretched", "zoom"][..]),
        (46, &["axes-scaled"][..]),
    ] {
        let (verdict, said, left) = cases[seed].diagnose_given(programs::Given::Depth);
        assert_eq!(verdict, Verdict::Explained, "seed {seed}: {said:?}");
        // A handful of edge pixels at most (each left thousands before).
        assert!(left <= 20, "seed {seed}: {left} px left, {said:?}");
        for word in named {
            assert!(
                said.iter()
                    .any(|s| s == word || s.starts_with(&format!("{word} "))),
                "seed {seed}: {word} not in {said:?}"
            );
        }
    }
}

/// A program that flips its picture vertically and scales its axes is never said to mirror it:
/// on scene1_02, alike both ways, the flip and the mirror draw the same pixels, so the answer is
/// the tie of the two ("one of"). Two programs of the graded class (`examples/grade_class.rs`,
/// students 37 and 53) were said as `mirrored + axes-scaled`, the rival that flips dropped as
/// farther from the course's map.
#[test]
fn a_vertical_flip_with_scaled_axes_is_never_said_as_a_mirror() {
    use raytracer::compare::Deviation;
    for seed in [37, 53] {
        let program = student::draw_program(&mut student::Draw::new(seed), false);
        assert!(program.upside_down && !program.mirrored, "{program:?}");
        let answer = answer_of("scene1_02", &program, (8.0, 12.0), (8.0, 12.0));
        let words = |list: &[Deviation]| -> Vec<String> {
            list.iter().map(|d| d.word().to_owned()).collect()
        };
        let stated = words(answer.stated());
        assert!(
            !stated.contains(&"mirrored".to_owned()),
            "seed {seed}: {stated:?}"
        );
        let ties: Vec<Vec<String>> = answer.alternatives().iter().map(|a| words(a)).collect();
        assert!(
            ties.iter()
                .any(|t| t.contains(&"flipped-vertically".to_owned())),
            "seed {seed}: {stated:?}, ties {ties:?}"
        );
    }
}
