//! Settings saved by an earlier viewer still load: `tests/regressions/viewer-settings-3a2a41d.ron`
//! is what the viewer at revision 3a2a41d (before its state was regrouped by feature) wrote to
//! eframe's storage under its key, with every setting moved off its default (the few its writer
//! was not given were then edited by hand, in the same notation). The viewer starts
//! from it as it would after a restart, and everything comes back; what it saves again loads the
//! same.
#![cfg(feature = "gui")]

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use egui_kittest::Harness;
use raytracer::app::ViewerApp;
use raytracer::app::settings::{ExportFormat, Settings};
use raytracer::cli::ViewerRequest;
use raytracer::export::ExtraDepth;
use raytracer::render::depth_map::DepthColourMap;
use raytracer::render::{Filter, Sampler};

/// eframe's storage in memory.
#[derive(Default)]
struct Memory(BTreeMap<String, String>);

impl eframe::Storage for Memory {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }
    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_owned(), value);
    }
    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }
    fn flush(&mut self) {}
}

/// The viewer started with no scene named, on `storage` (as after a restart).
fn restarted(storage: Memory) -> Harness<'static, ViewerApp> {
    let storage: &'static Memory = Box::leak(Box::new(storage));
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1280.0, 720.0))
        .build_eframe(move |cc| {
            cc.storage = Some(storage);
            ViewerApp::new(cc, ViewerRequest::default())
        });
    common::settle(&mut harness);
    harness
}

fn fixture() -> Memory {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/regressions/viewer-settings-3a2a41d.ron");
    let mut storage = Memory::default();
    storage.0.insert(
        eframe::APP_KEY.to_owned(),
        std::fs::read_to_string(path).unwrap(),
    );
    storage
}

#[test]
fn settings_saved_by_an_earlier_viewer_still_load() {
    // The fixture's last scene is relative: the tests run in the crate's folder.
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
    let mut harness = restarted(fixture());
    let app = harness.state();
    let settings = app.settings();
    assert_eq!(settings.export.path, "shots/");
    assert_eq!(settings.export.format, ExportFormat::Tga);
    assert!(!settings.export.legend);
    assert!(!settings.export.side_by_side);
    assert!(!settings.export.displayed_size);
    assert_eq!(settings.export.size_px, [640, 480]);
    assert_eq!(settings.export.extra_depth, ExtraDepth::Png16);
    assert_eq!(settings.export.scene_path, "mine.txt");
    assert!(!settings.depth.mark_no_hit);
    assert!(settings.depth.log_counts);
    let sampling = settings.quality.sampling.expect("16 jittered samples");
    assert_eq!(sampling.samples, 16);
    assert_eq!(sampling.sampler, Sampler::Jittered);
    assert_eq!(sampling.filter, Filter::Tent { radius: 1.0 });
    assert_eq!(settings.depth.colour_map, DepthColourMap::Viridis);
    assert!(settings.depth.follow);
    assert_eq!(settings.depth.auto_cut_percent, 2.5);
    let named = &settings.views.named["scenes/scene1_02.txt"];
    assert_eq!(named[0].name, "left side");
    // The last scene is open again, in the camera it was last seen with (its depth range is
    // refitted: "follow" is on).
    let key = PathBuf::from("scenes/scene1_02.txt");
    assert_eq!(app.loaded_scene().path.as_deref(), Some(key.as_path()));
    let view = app.view();
    assert_eq!(view.center_world.to_array(), [1.0, 2.0, 30.0]);
    assert_eq!(view.size_world, 7.5);
    // The controls panel stays closed: the Controls button is not selected.
    assert!(!controls_open(&harness));

    // What it saves loads back the same.
    let mut saved = Memory::default();
    eframe::App::save(harness.state_mut(), &mut saved);
    let again: Settings =
        eframe::get_value(&saved, eframe::APP_KEY).expect("the saved settings parse");
    assert_eq!(&again, harness.state().settings());
}

/// Whether the controls panel is on screen (its first slider is).
fn controls_open(harness: &Harness<'static, ViewerApp>) -> bool {
    use egui_kittest::kittest::Queryable;
    harness
        .query_by_role_and_label(egui::accesskit::Role::Slider, "centre x")
        .is_some()
}
