//! The export's names, plans and files.
use super::*;
use crate::render::depth_map::DepthRange;
use crate::render::{Filter, Sampler, Sampling, render_with};
use crate::scene::{load_scene, parse_scene};

#[test]
fn export_paths_add_suffixes_and_keep_the_folder() {
    let paths = ExportPaths::new(Path::new("shots/view.tga"), ImageFormat::Png, "s");
    assert_eq!(paths.colour, Path::new("shots/view_colour.tga"));
    assert_eq!(paths.depth, Path::new("shots/view_depth.tga"));
    assert_eq!(paths.side_by_side, Path::new("shots/view_both.tga"));
    let paths = ExportPaths::new(Path::new("view"), ImageFormat::Png, "s");
    assert_eq!(paths.colour, Path::new("view_colour.png"));
    let paths = ExportPaths::new(Path::new("view.v2"), ImageFormat::Tga, "s");
    assert_eq!(paths.depth, Path::new("view.v2_depth.tga"));
    // Into a folder: named after the scene.
    let paths = ExportPaths::new(Path::new("shots/"), ImageFormat::Png, "scene1_02");
    assert_eq!(paths.colour, Path::new("shots/scene1_02_colour.png"));
}

#[test]
fn the_export_path_follows_the_scene_unless_the_user_named_it() {
    let follow = |path: &str, old: &str, new: &str| export_path_following(path, old, new);
    assert_eq!(
        follow("raytracer.png", "raytracer", "scene1_04").as_deref(),
        Some("scene1_04.png")
    );
    assert_eq!(
        follow("shots/scene1_04.tga", "scene1_04", "scene1_02").as_deref(),
        Some("shots/scene1_02.tga")
    );
    // The default name follows whatever scene was open before.
    assert_eq!(
        follow("raytracer.png", "scene1_01", "scene1_02").as_deref(),
        Some("scene1_02.png")
    );
    assert_eq!(follow("mine.png", "scene1_04", "scene1_02"), None);
    assert_eq!(follow("shots/", "scene1_04", "scene1_02"), None);
    assert_eq!(follow("scene1_02.png", "scene1_01", "scene1_02"), None);
}

#[test]
fn a_folder_export_is_named_after_the_scene_and_needs_its_folder() {
    assert_eq!(
        name_in_folder(Some(Path::new("scenes/scene1_02.txt"))),
        "scene1_02"
    );
    assert_eq!(name_in_folder(None), DEFAULT_EXPORT_NAME);
    assert_eq!(
        export_folder(Path::new("shots/new/")),
        Some(PathBuf::from("shots/new/"))
    );
    assert_eq!(
        export_folder(Path::new("shots/view.png")),
        Some(PathBuf::from("shots"))
    );
    assert_eq!(export_folder(Path::new("view.png")), None);
}

#[test]
fn saved_view_parses_back_to_the_same_camera() {
    let scene = parse_scene(include_str!("../../scenes/scene1_03.txt")).unwrap();
    let mut view = View::of_camera(&scene.camera, 10, 10, DepthRange::new(0.0, 1.0));
    view.center_world += glam::DVec3::new(0.1, 1.0 / 3.0, -7e-9);
    view.size_world = std::f64::consts::PI;
    view.direction_world = glam::DVec3::new(0.3, -0.2, -1.0 / 7.0);
    let folder = tempfile::tempdir().unwrap();
    let path = folder.path().join("view.txt");
    let mut set = crate::output::atomic::FileSet::new();
    stage_view_as_scene(&mut set, &scene, &view, &path).unwrap();
    set.commit().unwrap();
    let back = load_scene(&path).unwrap();
    assert_eq!(back, scene_with_view(&scene, &view));
    assert_eq!(back.camera.center_world, view.center_world);
    assert_eq!(back.camera.size_world, view.size_world);
}

#[test]
fn command_names_every_setting() {
    let plan = ExportPlan {
        base_path: PathBuf::from("shots/my view.png"),
        name_in_folder: DEFAULT_EXPORT_NAME.to_owned(),
        format: ImageFormat::Png,
        side_by_side: true,
        legend: true,
        colour_map: DepthColourMap::Turbo,
        extra_depth: ExtraDepth::Raw(RawDepthFormat::Exr),
        program: Some(PathBuf::from("/opt/it's/raytracer")),
    };
    let files = ExportFiles::of(&plan);
    assert_eq!(files.scene, Path::new("shots/my view_scene.txt"));
    assert_eq!(files.command, Path::new("shots/my view_command.sh"));
    assert_eq!(
        files.depth_raw.as_deref(),
        Some(Path::new("shots/my view_depth.exr"))
    );
    let scene = parse_scene(include_str!("../../scenes/scene1_01.txt")).unwrap();
    let view = View::of_camera(&scene.camera, 64, 48, DepthRange::new(9.0, 10.5));
    let quality = Quality {
        sampling: Some(Sampling {
            sampler: Sampler::Jittered,
            samples: 16,
            filter: Filter::Tent { radius: 1.5 },
            seed: 0,
        }),
    };
    let arguments = command_arguments(&plan, &files, &view, &quality);
    let line = arguments.join(" ");
    assert!(
        line.starts_with("-input my view_scene.txt -size 64 48"),
        "{line}"
    );
    for part in [
        "-depth 9 10.5 my view_depth.png",
        "-depth_colormap turbo",
        "-depth_raw my view_depth.exr",
        "-jittered_samples 16",
        "-tent_filter 1.5",
    ] {
        assert!(line.contains(part), "{part} in {line}");
    }
    let script = command_script(&arguments, plan.program.as_deref());
    assert!(
        script.contains(r"raytracer='/opt/it'\''s/raytracer'"),
        "{script}"
    );
    assert!(script.contains("'my view_scene.txt'"), "{script}");
    // The arguments are a valid command line.
    assert!(crate::cli::parse_command(arguments).is_ok());
}

#[test]
fn export_writes_every_file_and_the_command_reproduces_them() {
    let scene = parse_scene(include_str!("../../scenes/scene1_02.txt")).unwrap();
    let mut view = View::of_camera(&scene.camera, 48, 32, DepthRange::new(8.5, 11.0));
    view.center_world.x += 0.37;
    let quality = Quality::default();
    let frame = render_with(&scene, &view, &quality).unwrap();
    let folder = tempfile::tempdir().unwrap();
    for (colour_map, extra_depth) in [
        (DepthColourMap::Grey, ExtraDepth::Png16),
        (
            DepthColourMap::Viridis,
            ExtraDepth::Raw(RawDepthFormat::Pfm),
        ),
    ] {
        let plan = ExportPlan {
            base_path: folder
                .path()
                .join(format!("shot {}.tga", colour_map.name())),
            name_in_folder: DEFAULT_EXPORT_NAME.to_owned(),
            format: ImageFormat::Png,
            side_by_side: true,
            legend: false,
            colour_map,
            extra_depth,
            program: None,
        };
        let mut set = crate::output::atomic::FileSet::new();
        stage_export(&mut set, &scene, &view, &quality, &frame, &plan).unwrap();
        let written = set.commit().unwrap();
        assert_eq!(written.len(), 6, "{written:?}");
        assert!(written.iter().all(|p| p.exists()));
        // Run the command's arguments (from the export folder) into a second folder.
        let files = ExportFiles::of(&plan);
        let arguments = command_arguments(&plan, &files, &view, &quality);
        let again = tempfile::tempdir().unwrap();
        let rebased: Vec<String> = arguments
            .iter()
            .enumerate()
            .map(|(i, a)| {
                let is_input = i > 0 && arguments[i - 1] == "-input";
                let extension = Path::new(a).extension().and_then(|e| e.to_str());
                if matches!(extension, Some("tga" | "png" | "pfm")) {
                    again.path().join(a).display().to_string()
                } else if is_input {
                    folder.path().join(a).display().to_string()
                } else {
                    a.clone()
                }
            })
            .collect();
        let crate::cli::Command::Render(request) = crate::cli::parse_command(rebased).unwrap()
        else {
            panic!("a render command");
        };
        crate::cli::run::run(&request).unwrap();
        for path in [&files.images.colour, &files.images.depth]
            .into_iter()
            .chain(files.depth_raw.as_ref())
        {
            let name = path.file_name().unwrap();
            assert_eq!(
                std::fs::read(path).unwrap(),
                std::fs::read(again.path().join(name)).unwrap(),
                "{name:?} is reproduced byte for byte"
            );
        }
        if extra_depth == ExtraDepth::Png16 {
            let name = files.depth16.file_name().unwrap();
            assert_eq!(
                std::fs::read(&files.depth16).unwrap(),
                std::fs::read(again.path().join(name)).unwrap()
            );
        }
    }
}
