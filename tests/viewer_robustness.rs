//! The viewer under abuse: thousands of random slider values (extremes, NaN, infinities), typed
//! non-numbers in the value fields, and window sizes down to 0×0 — no panic, and afterwards the
//! viewer still renders the current view (seeded); three images dropped at once are refused with
//! a reason.
#![cfg(feature = "gui")]

use std::time::{Duration, Instant};

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT, Queryable};
use raytracer::render::rng::SplitMix64;

mod common;
#[path = "common/compare_run.rs"]
mod compare_run;

const SLIDERS: [&str; 12] = [
    "centre x",
    "centre y",
    "centre z",
    "size",
    "depth min",
    "depth max",
    "direction x",
    "direction y",
    "direction z",
    "up x",
    "up y",
    "up z",
];

const TYPED: [&str; 8] = ["abc", "", "-", "1e999", "nan", "-inf", "1,5", "0x10"];

fn hostile_value(rng: &mut SplitMix64) -> f64 {
    const EXTREMES: [f64; 10] = [
        0.0,
        -0.0,
        1e308,
        -1e308,
        1e-308,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1e150,
        -1e-9,
    ];
    if rng.unit() < 0.4 {
        EXTREMES[(rng.next_u64() % EXTREMES.len() as u64) as usize]
    } else {
        let magnitude = rng.log_uniform(1e-9, 1e9);
        if rng.unit() < 0.5 {
            -magnitude
        } else {
            magnitude
        }
    }
}

type Harness = egui_kittest::Harness<'static, raytracer::app::ViewerApp>;

/// The viewer is consistent after hostile input: once the worker is done, either the view is
/// renderable and the frame on screen is exactly its render, or it is not and the status bar
/// says why (and a frame from before stays on screen).
fn assert_consistent(harness: &mut Harness, step: usize) {
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        harness.state().wait_for_worker(Duration::from_millis(20));
        harness.step();
        let app = harness.state();
        let renderable = app.view().validate().is_ok();
        if renderable && app.frame_is_current() {
            let (frame, view) = app.shown_frame().unwrap();
            let expected = raytracer::render::render(&app.loaded_scene().scene, view).unwrap();
            assert!(
                *frame == expected,
                "step {step}: the frame is not the view's render"
            );
            return;
        }
        if !renderable && app.wait_for_worker(Duration::ZERO) {
            let (message, is_error) = app.message().expect("a message says why");
            assert!(
                is_error && message.starts_with("view: "),
                "step {step}: {message}"
            );
            assert!(
                app.shown_frame().is_some(),
                "step {step}: a frame stays on screen"
            );
            return;
        }
        assert!(
            Instant::now() < deadline,
            "step {step}: the viewer does not settle"
        );
    }
}

/// Two thousand hostile inputs in two runs of a thousand, each from its own seed: the two run
/// side by side (one run takes a core for its whole time).
#[test]
fn thousands_of_hostile_inputs_never_panic() {
    hostile_inputs_never_panic(0xAB05E);
}

#[test]
fn thousands_of_hostile_inputs_never_panic_from_another_seed() {
    hostile_inputs_never_panic(0x5EED2);
}

/// A thousand random inputs from `seed`: no panic, every kind of abuse done many times, and
/// afterwards the viewer renders the file's view again.
fn hostile_inputs_never_panic(seed: u64) {
    const STEPS: usize = 1_000;
    let mut harness = common::viewer(Some(common::scene_path("scene1_02.txt")));
    harness.get_by_label("Direction and up").click();
    harness.step();
    let mut rng = SplitMix64::new(seed);
    let sizes = [
        (0.0, 0.0),
        (1.0, 1.0),
        (5.0, 3.0),
        (320.0, 200.0),
        (1000.0, 700.0),
    ];
    let mut size = (1000.0, 700.0);
    // What was done: resizes, typed values, resets, slider values.
    let mut done = [0usize; 4];
    for step in 0..STEPS {
        // In a window this large every control is reachable; below it some may not be.
        let roomy = size.0 >= 1000.0;
        match rng.next_u64() % 10 {
            0 => {
                size = sizes[(rng.next_u64() % sizes.len() as u64) as usize];
                harness.set_size(egui::vec2(size.0, size.1));
                harness.step();
                // Narrow windows keep the controls in a drawer: open it, as a user would.
                if harness
                    .query_by_role_and_label(Role::Slider, SLIDERS[0])
                    .is_none()
                    && let Some(toggle) = harness.query_by_label("Controls")
                {
                    toggle.click();
                }
                done[0] += 1;
            }
            1 | 2 => {
                // Type a non-number into one of the value fields, then press Enter.
                let fields: Vec<_> = harness.query_all_by_role(Role::SpinButton).collect();
                if fields.is_empty() {
                    assert!(!roomy, "step {step}: no value field in a {size:?} window");
                } else {
                    let field = &fields[(rng.next_u64() % fields.len() as u64) as usize];
                    field.click();
                    field.type_text(TYPED[(rng.next_u64() % TYPED.len() as u64) as usize]);
                    harness.key_press(egui::Key::Enter);
                    done[1] += 1;
                }
            }
            3 => {
                // Narrow windows keep it in the toolbar's "More" menu.
                let in_sight = harness
                    .query_by_role_and_label(Role::Button, "Reset view")
                    .is_some();
                if !in_sight
                    && let Some(more) = harness.query_by_role_and_label(Role::Button, "More")
                {
                    more.click();
                    harness.step();
                    harness.step();
                }
                match harness.query_by_role_and_label(Role::Button, "Reset view") {
                    Some(button) => {
                        button.click();
                        done[2] += 1;
                    }
                    None => assert!(
                        size.0 < 320.0,
                        "step {step}: no Reset view in a {size:?} window"
                    ),
                }
            }
            _ => {
                let label = SLIDERS[(rng.next_u64() % SLIDERS.len() as u64) as usize];
                match harness.query_by_role_and_label(Role::Slider, label) {
                    Some(slider) => {
                        slider.set_value_accesskit(hostile_value(&mut rng));
                        done[3] += 1;
                    }
                    None => assert!(
                        !roomy,
                        "step {step}: no slider '{label}' in a {size:?} window"
                    ),
                }
            }
        }
        harness.step();
        if step % 100 == 99 {
            assert_consistent(&mut harness, step);
        }
    }
    // Every kind of abuse happened many times (the widgets were found, not skipped; the three
    // tiny sizes show no controls, so a reset is possible in about 2 of 5 steps that try one).
    assert!(
        done[0] > 40 && done[1] > 80 && done[2] > 20 && done[3] > 200,
        "{done:?}"
    );

    // Back to a sane window and the file's camera: the viewer renders again.
    harness.set_size(egui::vec2(1000.0, 700.0));
    harness.step();
    harness
        .get_by_role_and_label(Role::Button, "Reset view")
        .click();
    assert_consistent(&mut harness, STEPS);
    assert!(harness.state().view().validate().is_ok());
    let _ = harness.root().accesskit_node();
}

/// Three images dropped at once: the viewer cannot know which two make the pair, so it compares
/// none and says so in the status bar, naming the three and what to drop instead; an image
/// dropped alone after it is compared.
#[test]
fn three_images_dropped_at_once_are_refused_with_a_reason_and_none_is_judged() {
    let folder = tempfile::tempdir().unwrap();
    compare_run::write_mistaken(folder.path(), raytracer::compare::MistakeSet::NONE, "tga");
    std::fs::copy(
        folder.path().join("colour.tga"),
        folder.path().join("other.tga"),
    )
    .unwrap();
    let mut harness = common::viewer(Some(compare_run::path(compare_run::SCENE)));
    common::settle(&mut harness);
    for name in ["colour.tga", "depth.tga", "other.tga"] {
        let file = common::DroppedOnTheWindow(folder.path().join(name));
        harness
            .input_mut()
            .dropped_files
            .push(std::sync::Arc::new(file));
    }
    harness.run_steps(3);
    common::settle(&mut harness);
    let app = harness.state();
    assert!(
        !app.comparing() && app.comparison().is_none(),
        "an image of the three was compared"
    );
    let (message, error) = app.message().unwrap();
    let said = "3 images dropped at once (colour.tga, depth.tga, other.tga): none was compared; \
                the viewer judges one colour image and its depth image together: drop those \
                two, or one image alone";
    assert!(error && message == said, "{message}");
    assert!(
        common::label_shown(&harness, said),
        "the status bar shows it"
    );
    let file = common::DroppedOnTheWindow(folder.path().join("depth.tga"));
    harness
        .input_mut()
        .dropped_files
        .push(std::sync::Arc::new(file));
    let deadline = Instant::now() + Duration::from_secs(60);
    while harness.state().comparing() || harness.state().comparison().is_none() {
        harness.step();
        assert!(
            Instant::now() < deadline,
            "the image dropped alone was not compared"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}
