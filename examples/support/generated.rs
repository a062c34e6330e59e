//! The generated corpus: seeded programs of the student caster (`student.rs`) on the course
//! scenes, each diagnosed from its colour and depth images and judged (`judge.rs`). Shared by
//! `tests/generated.rs` (the rules) and `examples/diagnosis_report.rs` (`docs/diagnosis.md`); the
//! including file also includes `student.rs` as `student` and `judge.rs` as `judge`.

#![allow(dead_code)]

use std::path::Path;

use raytracer::compare::{Deviation, Theirs, diagnose};
use raytracer::render::View;
use raytracer::render::depth_map::DepthRange;
use raytracer::scene::{Scene, load_scene};

use super::judge::{Verdict, judge};
use super::student::{Draw, Program, draw_program, render};

/// The image sizes drawn from.
const SIZES: [(u32, u32); 3] = [(200, 200), (160, 90), (90, 140)];

/// Which of a case's images are compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Given {
    /// The colour and the depth image together.
    Both,
    /// The colour image alone.
    Colour,
    /// The depth image alone, with its range.
    Depth,
}

/// One generated case.
pub(crate) struct Case {
    pub(crate) seed: u64,
    pub(crate) scene_name: &'static str,
    pub(crate) scene: Scene,
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) range: (f64, f64),
    pub(crate) program: Program,
}

/// The first `count` cases (seeds 0, 1, …).
pub(crate) fn cases(count: u64) -> Vec<Case> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    (0..count)
        .map(|seed| {
            let mut draw = Draw::new(seed);
            // The course scenes and the depth ranges of their command lines.
            let scenes = super::course::ranges();
            let (scene_name, dmin, dmax) = scenes[draw.below(scenes.len() as u64) as usize];
            let (width, height) = SIZES[draw.below(SIZES.len() as u64) as usize];
            let program = draw_program(&mut draw, width != height);
            let scene =
                load_scene(&root.join(format!("scenes/{scene_name}.txt"))).expect("a course scene");
            Case {
                seed,
                scene_name,
                scene,
                width,
                height,
                range: (dmin, dmax),
                program,
            }
        })
        .collect()
}

impl Case {
    /// The images the case's program makes.
    pub(crate) fn images(&self) -> (image::RgbImage, image::RgbImage) {
        render(
            &self.program,
            &self.scene,
            self.width,
            self.height,
            self.range.0,
            self.range.1,
        )
    }

    /// Diagnoses the case's images: the verdict, the statements said (with values; "one of"
    /// for a near tie), the pixels left unexplained.
    pub(crate) fn diagnose(&self) -> (Verdict, Vec<String>, usize) {
        self.diagnose_given(Given::Both)
    }

    /// Diagnoses the case's images `given` (both, or one alone with the range of its command
    /// line), as [`Self::diagnose`] does.
    pub(crate) fn diagnose_given(&self, given: Given) -> (Verdict, Vec<String>, usize) {
        let (colour, depth) = self.images();
        let view = View::of_camera(
            &self.scene.camera,
            self.width,
            self.height,
            DepthRange::new(self.range.0, self.range.1),
        );
        let theirs = Theirs {
            colour: (given != Given::Depth).then_some(&colour),
            depth: (given != Given::Colour).then_some(&depth),
        };
        let answer = diagnose(&self.scene, &view, theirs);
        let images = if given == Given::Both { 2 } else { 1 };
        let names = |list: &[Deviation]| -> Vec<String> {
            list.iter().map(|d| d.word().to_owned()).collect()
        };
        let stated: Vec<String> = [names(answer.stated()), names(answer.partial())].concat();
        let alternatives: Vec<Vec<String>> =
            answer.alternatives().iter().map(|a| names(a)).collect();
        let pixels = images * u64::from(self.width) * u64::from(self.height);
        let verdict = judge(
            answer.differing_exact == 0,
            &stated,
            &alternatives,
            answer.unexplained_pixels() as u64,
            pixels,
            &self.program.truth(),
        );
        let mut said: Vec<String> = answer
            .stated()
            .iter()
            .map(Deviation::name_and_values)
            .collect();
        said.extend(
            answer
                .partial()
                .iter()
                .map(|d| format!("{} (in part)", d.name_and_values())),
        );
        if !answer.alternatives().is_empty() {
            let sets: Vec<String> = answer
                .alternatives()
                .iter()
                .map(|a| {
                    a.iter()
                        .map(Deviation::name_and_values)
                        .collect::<Vec<_>>()
                        .join(" + ")
                })
                .collect();
            said.push(format!("one of: {}", sets.join(" | ")));
        }
        (verdict, said, answer.unexplained_pixels())
    }
}
