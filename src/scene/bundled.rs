//! The scenes that ship inside the program: the course's seven and the showcase scenes, offered
//! by the viewer's "Course scenes" menu (in a page, where no folder of scenes is at hand, they
//! are the ones a user can open without a file). The files themselves are in `scenes/`.

/// Each bundled scene: its file name (as in `scenes/`) and its text.
pub const BUNDLED_SCENES: &[(&str, &str)] = &[
    ("scene1_01.txt", include_str!("../../scenes/scene1_01.txt")),
    ("scene1_02.txt", include_str!("../../scenes/scene1_02.txt")),
    ("scene1_03.txt", include_str!("../../scenes/scene1_03.txt")),
    ("scene1_04.txt", include_str!("../../scenes/scene1_04.txt")),
    ("scene1_05.txt", include_str!("../../scenes/scene1_05.txt")),
    ("scene1_06.txt", include_str!("../../scenes/scene1_06.txt")),
    ("scene1_07.txt", include_str!("../../scenes/scene1_07.txt")),
    (
        "showcase_far_from_origin.txt",
        include_str!("../../scenes/showcase_far_from_origin.txt"),
    ),
    (
        "showcase_skewed_camera.txt",
        include_str!("../../scenes/showcase_skewed_camera.txt"),
    ),
    (
        "showcase_torus_knot.txt",
        include_str!("../../scenes/showcase_torus_knot.txt"),
    ),
];

/// The course's seven command lines (`scenes/assignment1.commands`), as the handout gives them:
/// each names a bundled scene, the image size and the depth range of its depth image.
pub const COURSE_COMMANDS: &str = include_str!("../../scenes/assignment1.commands");

/// The course's command lines as (scene file name, depth range's DMIN and DMAX): the scene of
/// `-input` and the range of `-depth`, of each line of [`COURSE_COMMANDS`] that gives both.
pub fn course_lines() -> Vec<(&'static str, f64, f64)> {
    COURSE_COMMANDS
        .lines()
        .filter(|line| !line.trim_start().starts_with('#'))
        .filter_map(|line| {
            let words: Vec<&str> = line.split_whitespace().collect();
            let after = |flag: &str| words.iter().position(|w| *w == flag).map(|i| i + 1);
            let scene = *words.get(after("-input")?)?;
            let depth = after("-depth")?;
            let min = words.get(depth)?.parse().ok()?;
            let max = words.get(depth + 1)?.parse().ok()?;
            Some((scene, min, max))
        })
        .collect()
}

/// The depth range of the course's command line for the scene file named `file_name` (the
/// course's scenes by their names, `scene1_04.txt`, any case), if it is one of them.
pub fn course_range_of(file_name: &str) -> Option<(f64, f64)> {
    course_lines()
        .into_iter()
        .find(|(scene, _, _)| scene.eq_ignore_ascii_case(file_name))
        .map(|(_, min, max)| (min, max))
}

#[cfg(test)]
mod tests {
    use super::{BUNDLED_SCENES, course_lines};

    /// The course's seven lines, each naming a bundled scene and a depth range.
    #[test]
    fn the_course_lines_name_bundled_scenes_and_ranges() {
        let lines = course_lines();
        assert_eq!(lines.len(), 7);
        assert_eq!(lines[3], ("scene1_04.txt", 12.0, 17.0));
        for (scene, min, max) in lines {
            assert!(
                BUNDLED_SCENES.iter().any(|(name, _)| *name == scene),
                "{scene}"
            );
            assert!(min < max);
        }
    }

    /// Every scene in `scenes/` is bundled, under its own name, and each parses.
    #[test]
    fn every_scene_file_is_bundled_and_parses() {
        let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let mut on_disk: Vec<String> = std::fs::read_dir(&folder)
            .unwrap()
            .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|name| {
                std::path::Path::new(name)
                    .extension()
                    .is_some_and(|extension| extension.eq_ignore_ascii_case("txt"))
            })
            .collect();
        on_disk.sort();
        let bundled: Vec<String> = BUNDLED_SCENES
            .iter()
            .map(|(name, _)| name.to_string())
            .collect();
        assert_eq!(bundled, on_disk);
        for (name, text) in BUNDLED_SCENES {
            assert_eq!(*text, std::fs::read_to_string(folder.join(name)).unwrap());
            crate::scene::parse_scene(text).unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }
}
