//! The viewer's writes, driven through its buttons (egui_kittest): it asks before replacing any
//! file and warns when one is the open scene, writes into a folder when given one (refusing an
//! unusable size before it offers to make one), and gives
//! written files the modes the command line gives them; "Course files" writes the course's images
//! and their command line, and exports are named after the scene; a scene file dropped on the
//! window opens.

mod common;

use std::os::unix::fs::PermissionsExt as _;
use std::path::Path;

use common::{click, scene_path, settle, viewer};
use egui_kittest::kittest::Queryable;

/// Clicks `label`, lets the viewer settle and draws two more frames (a modal window appears in
/// the accessibility tree on its second frame).
fn press(harness: &mut egui_kittest::Harness<'static, raytracer::app::ViewerApp>, label: &str) {
    click(harness, label);
    settle(harness);
    harness.run_steps(2);
}

fn mode(path: &Path) -> u32 {
    std::fs::metadata(path).unwrap().permissions().mode() & 0o777
}

/// The process's umask, as the kernel reports it.
fn umask() -> u32 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status.lines().find(|l| l.starts_with("Umask:")).unwrap();
    u32::from_str_radix(line.split_whitespace().nth(1).unwrap(), 8).unwrap()
}

#[test]
fn saving_the_view_over_a_file_asks_first_and_cancel_keeps_it() {
    let folder = tempfile::tempdir().unwrap();
    let target = folder.path().join("view.txt");
    std::fs::write(&target, b"my notes").unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    harness.state_mut().settings_mut().export.scene_path = target.display().to_string();
    press(&mut harness, "Save view as scene");
    assert!(harness.query_by_label("Replace this file?").is_some());
    assert_eq!(std::fs::read(&target).unwrap(), b"my notes", "nothing yet");
    press(&mut harness, "Cancel");
    assert!(harness.query_by_label("Replace this file?").is_none());
    assert_eq!(std::fs::read(&target).unwrap(), b"my notes", "cancelled");
    // Asked again, and this time replaced.
    press(&mut harness, "Save view as scene");
    press(&mut harness, "Replace");
    let saved = raytracer::scene::load_scene(&target).unwrap();
    assert_eq!(
        saved.camera.center_world,
        harness.state().view().center_world
    );
}

#[test]
fn saving_over_the_open_scene_warns_and_keeps_the_saved_message() {
    let folder = tempfile::tempdir().unwrap();
    let scene = folder.path().join("open.txt");
    std::fs::copy(scene_path("scene1_02.txt"), &scene).unwrap();
    let original = std::fs::read(&scene).unwrap();
    let mut harness = viewer(Some(scene.clone()));
    harness.state_mut().view_mut().center_world.x += 0.25;
    settle(&mut harness);
    harness.state_mut().settings_mut().export.scene_path = scene.display().to_string();
    press(&mut harness, "Save view as scene");
    assert!(
        harness
            .query_by_label_contains("the scene file on screen")
            .is_some(),
        "the open scene gets a warning of its own"
    );
    assert_eq!(std::fs::read(&scene).unwrap(), original);
    press(&mut harness, "Replace");
    // The file changed on disk, so it reloads (the file's camera is now the saved view); the
    // message still says what was saved.
    let saved_center = harness.state().view().center_world;
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
    while harness.state().loaded_scene().file_view.center_world != saved_center {
        assert!(
            std::time::Instant::now() < deadline,
            "the saved scene was not reloaded"
        );
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    settle(&mut harness);
    let (message, is_error) = harness.state().message().unwrap();
    assert!(
        !is_error && message.contains("saved the view as"),
        "{message}"
    );
    let saved = raytracer::scene::load_scene(&scene).unwrap();
    assert_eq!(
        saved.camera.center_world,
        harness.state().view().center_world
    );
}

#[test]
fn an_export_over_existing_files_lists_them_and_waits_for_a_yes() {
    let folder = tempfile::tempdir().unwrap();
    let colour = folder.path().join("shot_colour.png");
    std::fs::write(&colour, b"an earlier shot").unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    harness.state_mut().settings_mut().export.path =
        folder.path().join("shot.png").display().to_string();
    press(&mut harness, "Export to path");
    // The folder named, then the file to be replaced.
    let named = format!("In the folder {}:", folder.path().display());
    assert!(harness.query_by_label(&named).is_some(), "{named}");
    assert!(harness.query_by_label("shot_colour.png").is_some());
    assert_eq!(std::fs::read(&colour).unwrap(), b"an earlier shot");
    assert_eq!(std::fs::read_dir(folder.path()).unwrap().count(), 1);
    press(&mut harness, "Replace");
    assert!(image::open(&colour).is_ok(), "replaced by the export");
    assert!(folder.path().join("shot_depth.png").exists());
}

#[test]
fn a_folder_path_exports_into_the_folder() {
    let folder = tempfile::tempdir().unwrap();
    let shots = folder.path().join("shots");
    std::fs::create_dir(&shots).unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    for typed in [format!("{}/", shots.display()), shots.display().to_string()] {
        for entry in std::fs::read_dir(&shots).unwrap() {
            std::fs::remove_file(entry.unwrap().path()).unwrap();
        }
        harness.state_mut().settings_mut().export.path = typed.clone();
        press(&mut harness, "Export to path");
        let (message, is_error) = harness.state().message().unwrap();
        assert!(!is_error, "{typed}: {message}");
        // Named after the scene file.
        assert!(shots.join("scene1_02_colour.png").exists(), "{typed}");
        assert!(shots.join("scene1_02_command.sh").exists(), "{typed}");
        assert_eq!(
            std::fs::read_dir(folder.path()).unwrap().count(),
            1,
            "{typed}: nothing beside the folder"
        );
    }
}

#[test]
fn a_missing_folder_is_created_when_the_user_agrees() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let missing = folder.path().join("new").join("deeper");
    for typed in [
        format!("{}/", missing.display()),
        missing.join("view.png").display().to_string(),
    ] {
        // Cancel: nothing is created.
        harness.state_mut().settings_mut().export.path = typed.clone();
        press(&mut harness, "Export to path");
        assert!(
            harness.query_by_label("Create this folder?").is_some(),
            "{typed}: asked"
        );
        press(&mut harness, "Cancel");
        assert_eq!(
            std::fs::read_dir(folder.path()).unwrap().count(),
            0,
            "{typed}"
        );
        // Yes: the folder is made and the export written into it.
        press(&mut harness, "Export to path");
        press(&mut harness, "Create the folder and export");
        settle(&mut harness);
        let (message, is_error) = harness.state().message().unwrap();
        assert!(!is_error, "{typed}: {message}");
        let colour = if typed.ends_with('/') {
            "scene1_02_colour.png"
        } else {
            "view_colour.png"
        };
        assert!(missing.join(colour).exists(), "{typed}: {message}");
        std::fs::remove_dir_all(folder.path().join("new")).unwrap();
    }
}

#[test]
fn an_export_at_an_unusable_size_is_refused_before_a_folder_is_offered() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    let missing = folder.path().join("new");
    let export = &mut harness.state_mut().settings_mut().export;
    export.path = format!("{}/", missing.display());
    // Each side within the size fields' range, the whole over the pixel limit.
    export.displayed_size = false;
    export.size_px = [16_384, 16_384];
    press(&mut harness, "Export to path");
    assert!(harness.query_by_label("Create this folder?").is_none());
    let (message, is_error) = harness.state().message().unwrap();
    assert!(is_error && message.starts_with("export: "), "{message}");
    assert!(!missing.exists());
}

#[test]
fn exported_files_follow_the_umask_and_replaced_ones_keep_their_mode() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    harness.state_mut().settings_mut().export.path =
        folder.path().join("shot.png").display().to_string();
    press(&mut harness, "Export to path");
    let new_mode = 0o666 & !umask();
    assert_eq!(mode(&folder.path().join("shot_colour.png")), new_mode);
    assert_eq!(mode(&folder.path().join("shot_scene.txt")), new_mode);
    assert_eq!(
        mode(&folder.path().join("shot_command.sh")),
        0o777 & !umask(),
        "the script is executable"
    );
    // Replaced: the mode the file had stays.
    let colour = folder.path().join("shot_colour.png");
    std::fs::set_permissions(&colour, std::fs::Permissions::from_mode(0o640)).unwrap();
    press(&mut harness, "Export to path");
    press(&mut harness, "Replace");
    assert_eq!(mode(&colour), 0o640);
}

#[test]
fn the_exported_command_script_renders_the_same_files_from_anywhere() {
    // The viewer as the binary starts it: it knows its own path, which the script runs.
    let folder = tempfile::tempdir().unwrap();
    let mut harness = egui_kittest::Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        .build_eframe(|cc| {
            raytracer::app::ViewerApp::new(
                cc,
                raytracer::cli::ViewerRequest {
                    input: Some(scene_path("scene1_04.txt")),
                    program: Some(env!("CARGO_BIN_EXE_raytracer").into()),
                    ..Default::default()
                },
            )
        });
    settle(&mut harness);
    harness.state_mut().view_mut().center_world.y += 0.3;
    settle(&mut harness);
    harness.state_mut().settings_mut().export.path =
        folder.path().join("shot.tga").display().to_string();
    press(&mut harness, "Export to path");
    let names = ["shot_colour.tga", "shot_depth.tga"];
    let exported: Vec<Vec<u8>> = names
        .iter()
        .map(|name| std::fs::read(folder.path().join(name)).unwrap())
        .collect();
    for name in names {
        std::fs::remove_file(folder.path().join(name)).unwrap();
    }
    // Run from another folder, with no raytracer on PATH.
    let elsewhere = tempfile::tempdir().unwrap();
    let output = std::process::Command::new("sh")
        .arg(folder.path().join("shot_command.sh"))
        .current_dir(elsewhere.path())
        .env("PATH", "/usr/bin:/bin")
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    for (name, bytes) in names.iter().zip(&exported) {
        let again = std::fs::read(folder.path().join(name)).unwrap();
        assert!(&again == bytes, "{name} is made again byte for byte");
    }
    assert_eq!(std::fs::read_dir(elsewhere.path()).unwrap().count(), 0);
}

#[test]
fn course_files_are_the_course_images_and_their_command_and_exports_are_named_after_the_scene() {
    let folder = tempfile::tempdir().unwrap();
    let mut harness = egui_kittest::Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        .build_eframe(|cc| {
            raytracer::app::ViewerApp::new(
                cc,
                raytracer::cli::ViewerRequest {
                    input: Some(scene_path("scene1_04.txt")),
                    program: Some(env!("CARGO_BIN_EXE_raytracer").into()),
                    ..Default::default()
                },
            )
        });
    settle(&mut harness);
    // Exports are named after the scene on screen.
    assert_eq!(harness.state().settings().export.path, "scene1_04.png");
    // A course scene opens with the course's range (its line's -depth 12 17).
    let range = harness.state().view().depth_range;
    assert_eq!((range.min_t, range.max_t), (12.0, 17.0));
    // The view moved, the range changed: the course files are still the course's command's,
    // and the message says whose range they are over.
    harness.state_mut().view_mut().center_world.y += 0.3;
    harness.state_mut().view_mut().depth_range =
        raytracer::render::depth_map::DepthRange::new(13.0, 15.5);
    settle(&mut harness);
    harness.state_mut().settings_mut().export.path =
        folder.path().join("scene1_04.png").display().to_string();
    press(&mut harness, "Course files");
    assert!(
        harness
            .state()
            .wait_for_worker(std::time::Duration::from_secs(20))
    );
    harness.run_steps(2);
    let (message, error) = harness.state().message().unwrap();
    assert!(!error, "{message}");
    assert!(
        message.starts_with(
            "wrote the course's files for scene1_04.txt (its line's -size 200 200 -depth 12 17):"
        ),
        "{message}"
    );
    let names = ["output1_04.tga", "depth1_04.tga"];
    // The course's colour image, pixel for pixel.
    let reference = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference");
    let colour = image::open(folder.path().join(names[0])).unwrap().to_rgb8();
    let course = image::open(reference.join("output1_04.png"))
        .unwrap()
        .to_rgb8();
    assert!(colour == course, "output1_04.tga is the course's");
    // Both are the course's command line's files, byte for byte.
    let by_command = tempfile::tempdir().unwrap();
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_raytracer"))
        .args(["-input", &scene_path("scene1_04.txt").display().to_string()])
        .args(["-size", "200", "200", "-output", names[0]])
        .args(["-depth", "12", "17", names[1]])
        .current_dir(by_command.path())
        .status()
        .unwrap();
    assert!(status.success());
    let mut written = Vec::new();
    for name in names {
        let path = folder.path().join(name);
        let bytes = std::fs::read(&path).unwrap();
        assert!(
            bytes == std::fs::read(by_command.path().join(name)).unwrap(),
            "{name} is the command line's"
        );
        written.push(bytes);
        std::fs::remove_file(&path).unwrap();
    }
    let script = std::fs::read_to_string(folder.path().join("command1_04.sh")).unwrap();
    assert!(
        script.contains("-size 200 200 -output output1_04.tga -depth 12 17 depth1_04.tga"),
        "{script}"
    );
    // The script makes the same files again, from anywhere.
    let elsewhere = tempfile::tempdir().unwrap();
    let output = std::process::Command::new("sh")
        .arg(folder.path().join("command1_04.sh"))
        .current_dir(elsewhere.path())
        .env("PATH", "/usr/bin:/bin")
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    for (name, bytes) in names.iter().zip(&written) {
        assert!(
            &std::fs::read(folder.path().join(name)).unwrap() == bytes,
            "{name} again, byte for byte"
        );
    }
    // A second time, the files exist: it asks before replacing them.
    press(&mut harness, "Course files");
    assert!(harness.query_by_label("Replace").is_some());
}

/// A scene that is not one of the course's (a course scene's text under another name): it opens
/// with the range of what its camera sees, and "Course files" writes at the course's size over
/// the range in use, and says so, with the range, in its message and its command line.
#[test]
fn course_files_of_a_scene_not_the_courses_say_which_range_they_used() {
    let folder = tempfile::tempdir().unwrap();
    let mine = folder.path().join("mine.txt");
    std::fs::copy(scene_path("scene1_04.txt"), &mine).unwrap();
    let mut harness = egui_kittest::Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        .build_eframe(|cc| {
            raytracer::app::ViewerApp::new(
                cc,
                raytracer::cli::ViewerRequest {
                    input: Some(mine.clone()),
                    ..Default::default()
                },
            )
        });
    settle(&mut harness);
    let range = harness.state().view().depth_range;
    assert!(
        (range.min_t, range.max_t) != (12.0, 17.0),
        "{range:?}: the course's range for a scene that is not the course's"
    );
    harness.state_mut().settings_mut().export.path =
        folder.path().join("mine.png").display().to_string();
    press(&mut harness, "Course files");
    assert!(
        harness
            .state()
            .wait_for_worker(std::time::Duration::from_secs(20))
    );
    harness.run_steps(2);
    let (message, error) = harness.state().message().unwrap();
    assert!(!error, "{message}");
    let said = format!("-size 200 200 -depth {} {};", range.min_t, range.max_t);
    assert!(message.contains(&said), "{message}");
    assert!(message.contains("not a course scene"), "{message}");
    let script = std::fs::read_to_string(folder.path().join("mine_command.sh")).unwrap();
    assert!(
        script.contains(&format!("-depth {} {}", range.min_t, range.max_t)),
        "{script}"
    );
}

#[test]
fn a_scene_file_dropped_on_the_window_opens() {
    let folder = tempfile::tempdir().unwrap();
    let dropped = folder.path().join("dropped.txt");
    std::fs::copy(scene_path("scene1_05.txt"), &dropped).unwrap();
    let mut harness = viewer(Some(scene_path("scene1_02.txt")));
    settle(&mut harness);
    harness
        .input_mut()
        .dropped_files
        .push(std::sync::Arc::new(common::DroppedOnTheWindow(
            dropped.clone(),
        )));
    settle(&mut harness);
    assert_eq!(
        harness.state().loaded_scene().path.as_deref(),
        Some(dropped.as_path())
    );
    assert_eq!(harness.state().scene_error(), None);
}

/// "Course files" never puts a student's files at risk: into a folder that does not exist it
/// offers to make it (Cancel makes nothing); over files there it names the folder, warns when one
/// is the image being compared (their program's output), and Enter answers no: the files keep
/// their bytes.
#[test]
fn course_files_offer_a_missing_folder_and_enter_keeps_the_files_they_would_replace() {
    let folder = tempfile::tempdir().unwrap();
    let missing = folder.path().join("out");
    let mut harness = viewer(Some(scene_path("scene1_04.txt")));
    harness.state_mut().settings_mut().export.path =
        missing.join("scene1_04.png").display().to_string();
    press(&mut harness, "Course files");
    assert!(harness.query_by_label("Create this folder?").is_some());
    press(&mut harness, "Cancel");
    assert!(!missing.exists());
    // Their program's output, compared, in the folder the course files go into.
    std::fs::create_dir(&missing).unwrap();
    let theirs = missing.join("output1_04.tga");
    let reference = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference");
    let mut image = image::open(reference.join("output1_04.png"))
        .unwrap()
        .to_rgb8();
    image.put_pixel(0, 0, image::Rgb([255, 0, 255]));
    image.save(&theirs).unwrap();
    let bytes = std::fs::read(&theirs).unwrap();
    common::compare_image(&mut harness, &theirs.display().to_string());
    press(&mut harness, "Course files");
    assert!(harness.query_by_label("Replace this file?").is_some());
    let named = format!("In the folder {}:", missing.display());
    assert!(common::label_shown(&harness, &named), "{named}");
    assert!(common::label_shown(&harness, "the image you are comparing"));
    harness.key_press(egui::Key::Enter);
    settle(&mut harness);
    harness.run_steps(2);
    assert!(harness.query_by_label("Replace this file?").is_none());
    assert!(
        std::fs::read(&theirs).unwrap() == bytes,
        "their file is kept"
    );
    assert!(!missing.join("depth1_04.tga").exists());
}
