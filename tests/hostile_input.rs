//! Hostile input in the normal test suite (the fuzz targets in `fuzz/` go further): arbitrary
//! bytes and word salad (property tests with proptest: shrunk and persisted when they fail) and
//! seeded mutations of the course scenes go through the parser and, when they parse, the renderer.
//! Nothing may panic, every error is one line with a position, and no
//! case hangs.

use std::path::Path;
use std::time::{Duration, Instant};

use proptest::prelude::*;
use raytracer::render::depth_map::DepthRange;
use raytracer::render::rng::SplitMix64;
use raytracer::render::{View, render};
use raytracer::scene::parse_scene_bytes;

/// A hang guard, not a speed claim: no case (parse + a small render) may take this long.
const CASE_LIMIT: Duration = Duration::from_secs(30);

fn course_scenes() -> Vec<String> {
    (1..=7)
        .map(|n| {
            let path =
                Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/scene1_0{n}.txt"));
            std::fs::read_to_string(path).unwrap()
        })
        .collect()
}

/// Parses and, if that succeeds, renders a small view; returns whether it parsed.
fn exercise(bytes: &[u8]) -> bool {
    let started = Instant::now();
    let parsed = match parse_scene_bytes(bytes) {
        Ok(scene) => {
            let mut view = View::of_camera(&scene.camera, 24, 16, DepthRange::new(0.0, 1.0));
            view.depth_range = raytracer::explore::initial_depth_range(&scene, &view);
            if let Ok(frame) = render(&scene, &view) {
                assert!(frame.t.iter().all(|t| !t.is_nan()), "NaN t");
                let _ = frame.depth_image(view.depth_range);
            }
            true
        }
        Err(error) => {
            // Every error renders as one line with a position.
            let message = error.to_string();
            assert!(!message.contains('\n'), "{message}");
            assert!(error.location.line >= 1 && error.location.column >= 1);
            false
        }
    };
    assert!(
        started.elapsed() < CASE_LIMIT,
        "case took {:?}: {:?}",
        started.elapsed(),
        String::from_utf8_lossy(&bytes[..bytes.len().min(200)])
    );
    parsed
}

const WORDS: &[&str] = &[
    "OrthographicCamera",
    "Background",
    "Materials",
    "Group",
    "Sphere",
    "MaterialIndex",
    "PhongMaterial",
    "Material",
    "numMaterials",
    "numObjects",
    "center",
    "direction",
    "up",
    "size",
    "radius",
    "color",
    "diffuseColor",
    "{",
    "}",
    "{{",
    "0",
    "1",
    "-1",
    "0.5",
    "1e308",
    "-1e308",
    "1e-320",
    "nan",
    "inf",
    "-0",
    "99999999999999999999",
    "1e150",
    "1e151",
    "\u{0}",
    "é",
    "#",
    "PerspectiveCamera",
    "Plane",
    "Transform",
];

/// The grammar's own words in random order, on lines of random length.
fn word_salad() -> impl Strategy<Value = Vec<u8>> {
    prop::collection::vec(
        (prop::sample::select(WORDS), prop::bool::weighted(0.8)),
        0..100,
    )
    .prop_map(|words| {
        let mut text = String::new();
        for (word, space) in words {
            text.push_str(word);
            text.push(if space { ' ' } else { '\n' });
        }
        text.into_bytes()
    })
}

proptest! {
    // Failing cases are shrunk and kept in proptest-regressions/ (committed), so they are tried
    // first on every later run.
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        exercise(&bytes);
    }

    #[test]
    fn word_salad_never_panics(bytes in word_salad()) {
        exercise(&bytes);
    }
}

/// Mutates a scene's words: delete, duplicate, swap in a hostile word, or truncate.
fn mutate(text: &str, rng: &mut SplitMix64) -> Vec<u8> {
    let mut words: Vec<String> = text.split_whitespace().map(str::to_owned).collect();
    for _ in 0..=(rng.next_u64() % 2) {
        if words.is_empty() {
            break;
        }
        let at = (rng.next_u64() % words.len() as u64) as usize;
        match rng.next_u64() % 5 {
            0 => {
                words.remove(at);
            }
            1 => {
                let word = words[at].clone();
                words.insert(at, word);
            }
            2 => words[at] = WORDS[(rng.next_u64() % WORDS.len() as u64) as usize].to_owned(),
            3 => words.truncate(at),
            _ => {
                // A number made extreme (the next numeric word from `at`).
                if let Some(number) = (at..words.len()).find(|&i| words[i].parse::<f64>().is_ok()) {
                    let exponent = (rng.next_u64() % 640) as i32 - 320;
                    words[number] = format!("{}e{exponent}", rng.uniform(-9.0, 9.0));
                }
            }
        }
    }
    words.join(" ").into_bytes()
}

#[test]
fn mutated_course_scenes_never_panic() {
    let scenes = course_scenes();
    let mut rng = SplitMix64::new(0x0005_CEE5);
    let mut parsed = 0;
    for case in 0..6_000 {
        let bytes = mutate(&scenes[case % scenes.len()], &mut rng);
        parsed += usize::from(exercise(&bytes));
    }
    // Some mutations (an extreme number in a valid place) still parse and are rendered.
    eprintln!("{parsed} of 6000 mutated scenes parsed and were rendered");
    assert!(parsed > 300, "only {parsed} mutated scenes parsed");
}

#[test]
fn deep_nesting_and_huge_counts_are_refused_quickly() {
    let camera = "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }\n";
    // 100,000 nested groups: refused at the depth limit, without exhausting the stack.
    let deep = format!("{camera}{}", "Group { numObjects 1 ".repeat(100_000));
    assert!(!exercise(deep.as_bytes()));
    // Counts far beyond memory allocate nothing.
    let huge = format!("{camera}Materials {{ numMaterials 18446744073709551615 }}");
    assert!(!exercise(huge.as_bytes()));
    let huge = format!("{camera}Group {{ numObjects 18446744073709551615 }}");
    assert!(!exercise(huge.as_bytes()));
}
