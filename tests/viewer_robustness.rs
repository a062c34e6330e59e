//! The viewer under abuse: thousands of random slider values (extremes, NaN, infinities), typed
//! non-numbers in the value fields, and window sizes down to 0×0 — no panic, and afterwards the
//! viewer still renders the current view. Seeded.
#![cfg(feature = "gui")]

use std::time::{Duration, Instant};

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT, Queryable};
use raytracer::render::rng::SplitMix64;

mod common;

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

#[test]
fn thousands_of_hostile_inputs_never_panic() {
    let mut harness = common::viewer(Some(common::scene_path("scene1_02.txt")));
    harness.get_by_label("Direction and up").click();
    harness.step();
    let mut rng = SplitMix64::new(0xAB05E);
    for _ in 0..2_000 {
        match rng.next_u64() % 10 {
            0 => {
                let sizes = [
                    (0.0, 0.0),
                    (1.0, 1.0),
                    (5.0, 3.0),
                    (320.0, 200.0),
                    (1000.0, 700.0),
                ];
                let (w, h) = sizes[(rng.next_u64() % sizes.len() as u64) as usize];
                harness.set_size(egui::vec2(w, h));
            }
            1 | 2 => {
                // Type a non-number into one of the value fields, then press Enter.
                let fields: Vec<_> = harness.query_all_by_role(Role::SpinButton).collect();
                if !fields.is_empty() {
                    let field = &fields[(rng.next_u64() % fields.len() as u64) as usize];
                    field.click();
                    field.type_text(TYPED[(rng.next_u64() % TYPED.len() as u64) as usize]);
                    harness.key_press(egui::Key::Enter);
                }
            }
            3 => {
                if let Some(button) = harness.query_by_role_and_label(Role::Button, "Reset view") {
                    button.click();
                }
            }
            _ => {
                let label = SLIDERS[(rng.next_u64() % SLIDERS.len() as u64) as usize];
                if let Some(slider) = harness.query_by_role_and_label(Role::Slider, label) {
                    slider.set_value_accesskit(hostile_value(&mut rng));
                }
            }
        }
        harness.step();
    }

    // Back to a sane window and the file's camera: the viewer renders again.
    harness.set_size(egui::vec2(1000.0, 700.0));
    harness.step();
    harness
        .get_by_role_and_label(Role::Button, "Reset view")
        .click();
    let deadline = Instant::now() + Duration::from_secs(60);
    loop {
        harness.step();
        if harness.state().frame_is_current() {
            break;
        }
        assert!(Instant::now() < deadline, "the viewer no longer renders");
        harness.state().wait_for_worker(Duration::from_millis(20));
    }
    let app = harness.state();
    let (frame, view) = app.shown_frame().unwrap();
    assert_eq!(view, app.view());
    assert!(*frame == raytracer::render::render(&app.loaded_scene().scene, view).unwrap());
    let _ = harness.root().accesskit_node();
}
