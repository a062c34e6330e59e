//! Parsing a big file on as many threads as the process may use. The text is cut into as many
//! chunks as threads, each starting at the first line past its share that starts with `Sphere`;
//! each chunk's run of sphere statements (through `Sphere` and `MaterialIndex` statements, to the
//! first other token, error or the chunk's end) is parsed ahead on a thread of its own while the
//! main parser reads the first chunk. When the main parser reaches a run's first line inside a
//! group it takes the run whole: the spheres (those before the run's first `MaterialIndex` get the
//! material in effect there), the `MaterialIndex` references with their lines made absolute, and
//! its place in the file; then it reads on from where the run stopped.
//!
//! Nothing about the result depends on the split: a run stops before any statement it cannot
//! parse, and the main parser reads that one itself (so errors have the same message and place),
//! and a run the main parser never reaches is dropped.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::channel;

use super::ahead::{Ahead, Run};
use super::error::{Location, ParseError};
use super::lexer::Token;
use super::model::{Scene, Sphere};
use super::parse::Parser;

#[cfg(test)]
thread_local! {
    /// Runs the main parser on this thread has taken (the tests check the chunks were used).
    static RUNS_TAKEN: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// Below this many bytes a file is parsed on one thread.
pub(super) const SPLIT_MIN_BYTES: usize = 4 << 20;

/// Each chunk is at least this many bytes (a thread's start costs more than parsing less).
const CHUNK_MIN_BYTES: usize = 1 << 20;

/// Parses `text` in chunks, one per thread the process may use (files of `split_min_bytes` or
/// more; others on this thread).
pub(super) fn parse_text(
    text: &str,
    progress: &dyn Fn(f64),
    split_min_bytes: usize,
) -> Result<Scene, ParseError> {
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let chunks = if split_min_bytes == 0 {
        // The fuzz target's path: split however small the text.
        threads.max(2)
    } else {
        threads.min(text.len() / CHUNK_MIN_BYTES)
    };
    parse_in_chunks(text, progress, split_min_bytes, chunks)
}

/// Parses `text` cut into `chunks` (at most; see [`split_points`]), the runs of all chunks but
/// the first parsed ahead on threads of their own, when it has `split_min_bytes` or more.
pub(super) fn parse_in_chunks(
    text: &str,
    progress: &dyn Fn(f64),
    split_min_bytes: usize,
    chunks: usize,
) -> Result<Scene, ParseError> {
    let starts = if text.len() >= split_min_bytes && chunks >= 2 {
        split_points(text, chunks)
    } else {
        Vec::new()
    };
    if starts.is_empty() {
        return Parser::new(text, progress).scene();
    }
    let cancelled = AtomicBool::new(false);
    std::thread::scope(|scope| {
        let cancelled = &cancelled;
        let mut aheads = VecDeque::new();
        for (index, &(line_start, token_offset)) in starts.iter().enumerate() {
            // Each run ends where the next chunk starts: no sphere is parsed twice.
            let end = starts.get(index + 1).map_or(text.len(), |&(next, _)| next);
            let ahead_text = &text[line_start..end];
            let (sender, run) = channel();
            let spawned = std::thread::Builder::new()
                .name("parse-ahead".into())
                .spawn_scoped(scope, move || {
                    // The main parser may have finished without it; then nobody listens.
                    let _ = sender.send(parse_run(ahead_text, cancelled));
                });
            if spawned.is_err() {
                // No more threads: the main parser reads the rest itself.
                break;
            }
            aheads.push_back(Ahead {
                token_offset,
                line_start,
                run,
            });
        }
        let mut parser = Parser::new(text, progress);
        parser.ahead = aheads;
        let scene = parser.scene();
        cancelled.store(true, Ordering::Relaxed);
        scene
    })
}

impl<'a> Parser<'a> {
    /// Takes the run parsed ahead if `token` (a `Sphere` inside a group) is where it starts;
    /// returns the spheres it added (0: parse the statement here).
    pub(super) fn take_run_at(&mut self, token: &Token<'a>) -> u64 {
        let offset = self.lexer.offset_of(token);
        // Runs this parser went past without reaching them at a sphere inside a group are
        // dropped.
        while self
            .ahead
            .front()
            .is_some_and(|ahead| ahead.token_offset < offset)
        {
            self.ahead.pop_front();
        }
        if self
            .ahead
            .front()
            .is_none_or(|ahead| ahead.token_offset != offset)
        {
            return 0;
        }
        let Some(ahead) = self.ahead.pop_front() else {
            return 0;
        };
        let line_start = ahead.line_start;
        let Ok(run) = ahead.run.recv() else { return 0 };
        if run.spheres.is_empty() {
            return 0;
        }
        let line = token.location.line;
        let inherited = self.current_material;
        let added = run.spheres.len();
        // Read on from where the run stopped; room for the rest is judged from there.
        self.lexer.continue_after(line_start, line, &run.end);
        if self.spheres_from_byte.is_none() {
            self.spheres_from_byte = Some(line_start);
        }
        self.reserve_once_past_threshold(added, run.material_references.len());
        self.spheres.extend(
            run.spheres
                .into_iter()
                .enumerate()
                .map(|(i, sphere)| Sphere {
                    material: if i < run.inheriting {
                        inherited
                    } else {
                        sphere.material
                    },
                    ..sphere
                }),
        );
        self.material_references
            .extend(run.material_references.into_iter().map(|(index, at)| {
                let at = Location {
                    line: at.line.saturating_add(line - 1),
                    column: at.column,
                };
                (index, at)
            }));
        #[cfg(test)]
        RUNS_TAKEN.with(|taken| taken.set(taken.get() + 1));
        if let Some(material) = run.material_after {
            self.current_material = material;
        }
        (self.progress)(self.lexer.share_consumed());
        added as u64
    }
}

/// Where the chunks after the first start: for each k of 1 … `chunks` − 1, the first line past
/// k/`chunks` of `text` whose first token is `Sphere`, each after the one before (fewer where none
/// is found).
pub(super) fn split_points(text: &str, chunks: usize) -> Vec<(usize, usize)> {
    let mut points: Vec<(usize, usize)> = Vec::new();
    for k in 1..chunks {
        let from = text.len() / chunks * k;
        let from = from.max(points.last().map_or(0, |&(line_start, _)| line_start + 1));
        match split_point_from(text, from) {
            Some(point) => points.push(point),
            None => break,
        }
    }
    points
}

/// The start of the first line in the second half of `text` whose first token is `Sphere`:
/// (line start, token offset).
#[cfg(test)]
pub(super) fn split_point(text: &str) -> Option<(usize, usize)> {
    split_point_from(text, text.len() / 2)
}

/// The start of the first line after byte `from` of `text` whose first token is `Sphere`: (line
/// start, token offset).
fn split_point_from(text: &str, from: usize) -> Option<(usize, usize)> {
    let bytes = text.as_bytes();
    let from = from.min(bytes.len());
    let mut line_start = bytes[from..].iter().position(|&b| b == b'\n')? + from + 1;
    while line_start < bytes.len() {
        let indent = bytes[line_start..]
            .iter()
            .position(|&b| !(b == b' ' || b == b'\t'))
            .unwrap_or(0);
        let token = line_start + indent;
        let after = bytes.get(token + 6).copied();
        if bytes[token..].starts_with(b"Sphere")
            && after.is_some_and(|b| b.is_ascii_whitespace() || b == b'{')
        {
            return Some((line_start, token));
        }
        line_start += bytes[line_start..].iter().position(|&b| b == b'\n')? + 1;
    }
    None
}

/// Parses the run of sphere statements at the start of `text` (the text from a line start).
fn parse_run<'a>(text: &'a str, cancelled: &AtomicBool) -> Run<'a> {
    let mut parser = Parser::new(text, &|_| {});
    let mut inheriting = None;
    let mut material_after = None;
    loop {
        let before = parser.lexer.clone();
        let spheres_before = parser.spheres.len();
        let references_before = parser.material_references.len();
        let cancel_point = parser.spheres.len().is_multiple_of(4096);
        let parsed = match parser.lexer.next().map(|token| token.text) {
            // The main parser stopped (an error, or the end): the run is not wanted.
            _ if cancel_point && cancelled.load(Ordering::Relaxed) => false,
            Some("Sphere") => parser.sphere().is_ok(),
            Some("MaterialIndex") => match parser.count("MaterialIndex") {
                Ok((index, location)) => {
                    parser.material_references.push((index, location));
                    inheriting.get_or_insert(parser.spheres.len());
                    let material = Some(u32::try_from(index).unwrap_or(u32::MAX));
                    parser.current_material = material;
                    material_after = Some(material);
                    true
                }
                Err(_) => false,
            },
            _ => false,
        };
        if !parsed {
            parser.spheres.truncate(spheres_before);
            parser.material_references.truncate(references_before);
            return Run {
                inheriting: inheriting.unwrap_or(parser.spheres.len()),
                spheres: parser.spheres,
                material_after,
                material_references: parser.material_references,
                end: before,
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::parse::{Parser, SPHERES_BEFORE_RESERVE};
    use super::super::read::parse_scene;
    use super::*;
    use std::fmt::Write as _;

    /// A scene text of `count` spheres over several megabytes: materials set every few spheres,
    /// some spheres before any `MaterialIndex` of a line, nested groups, odd spacing.
    fn big_text(count: usize) -> String {
        let mut text = String::from(
            "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }\n\
             Background { color 0 0 0 }\n\
             Materials { numMaterials 3\n\
             PhongMaterial { diffuseColor 1 0 0 }\n\
             PhongMaterial { diffuseColor 0 1 0 }\n\
             PhongMaterial { diffuseColor 0 0 1 } }\n",
        );
        let inner = 1000;
        let _ = writeln!(text, "Group {{\n numObjects {}", count - inner + 1);
        for i in 0..count {
            if i == count / 3 {
                let _ = writeln!(text, "  Group {{ numObjects {inner}");
            }
            if i % 7 == 3 {
                let _ = writeln!(text, "  MaterialIndex {}", i % 3);
            }
            let _ = writeln!(
                text,
                "\tSphere {{ center {} {}.25 -{} radius 0.{} }}",
                i % 101,
                i % 13,
                i % 17,
                1 + i % 9
            );
            if i == count / 3 + inner - 1 {
                let _ = writeln!(text, "  }}");
            }
        }
        text.push_str("}\n");
        text
    }

    fn sequential(text: &str) -> Result<crate::scene::Scene, crate::scene::ParseError> {
        Parser::new(text, &|_| {}).scene()
    }

    #[test]
    fn a_big_file_parses_on_two_threads_to_the_same_scene() {
        let text = big_text(120_000);
        assert!(text.len() > SPLIT_MIN_BYTES, "{} bytes", text.len());
        let (line_start, _) = split_point(&text).expect("a split point");
        assert!(line_start > text.len() / 2);
        let split = parse_scene(&text).unwrap();
        assert_eq!(split, sequential(&text).unwrap());
        assert_eq!(split.spheres.len(), 120_000);
    }

    #[test]
    fn any_number_of_chunks_gives_the_one_thread_scene_and_errors() {
        let text = big_text(60_000);
        let one_thread = sequential(&text).unwrap();
        for chunks in [2, 3, 5, 8, 16] {
            let points = split_points(&text, chunks);
            assert_eq!(points.len(), chunks - 1, "{chunks} chunks");
            assert!(points.windows(2).all(|pair| pair[0].0 < pair[1].0));
            RUNS_TAKEN.with(|taken| taken.set(0));
            let scene = parse_in_chunks(&text, &|_| {}, 0, chunks).unwrap();
            assert_eq!(scene, one_thread, "{chunks} chunks");
            // Every chunk after the first was parsed ahead and taken whole.
            assert_eq!(
                RUNS_TAKEN.with(std::cell::Cell::get),
                chunks - 1,
                "{chunks} chunks"
            );
        }
        // An error in each eighth of the file: the one a single thread finds.
        for eighth in 1..8 {
            let at = text.len() / 8 * eighth + 100;
            let line = at + text[at..].find("radius 0.").unwrap();
            let mut broken = text.clone();
            broken.replace_range(line..line + 9, "radius -0.");
            let expected = sequential(&broken).unwrap_err();
            for chunks in [3, 8] {
                let split = parse_in_chunks(&broken, &|_| {}, 0, chunks).unwrap_err();
                assert_eq!(split, expected, "eighth {eighth}, {chunks} chunks");
            }
        }
    }

    #[test]
    fn a_big_file_lists_its_spheres_in_one_block_not_by_doubling() {
        // 150,000 spheres: doubling from empty would leave room for 262,144; room made once for
        // the whole text (the second half's run included) leaves about a tenth spare.
        for count in [20_000, 150_000] {
            let text = big_text(count);
            let scene = parse_scene(&text).unwrap();
            assert_eq!(scene.spheres.len(), count);
            let spare = scene.spheres.capacity() as f64 / count as f64;
            assert!((1.0..1.25).contains(&spare), "{count}: room for {spare}×");
        }
    }

    /// [`big_text`] with `extra` more materials in its `Materials` block, ahead of every sphere.
    fn big_text_after_materials(count: usize, extra: usize) -> String {
        let mut materials = format!("Materials {{ numMaterials {}\n", 3 + extra);
        for i in 0..extra {
            let _ = writeln!(
                materials,
                "PhongMaterial {{ diffuseColor 0.{} 0.5 0.5 }}",
                i % 10
            );
        }
        big_text(count).replacen("Materials { numMaterials 3\n", &materials, 1)
    }

    #[test]
    fn room_for_the_spheres_is_judged_from_where_they_begin_not_from_a_materials_block() {
        // One thread: 100,000 materials (4.3 MB) ahead of 20,000 spheres. Judged from the file's
        // start, the first 4,096 spheres looked about 25 times sparser than they are and the list
        // grew by doubling past the room made (room for 1.6×).
        let text = big_text_after_materials(20_000, 100_000);
        assert!(text.contains("numMaterials 100003\n"));
        let scene = sequential(&text).unwrap();
        assert_eq!(scene.spheres.len(), 20_000);
        let spare = scene.spheres.capacity() as f64 / 20_000.0;
        assert!(
            (1.0..1.25).contains(&spare),
            "one thread: room for {spare}×"
        );

        // Four chunks, the first nearly all materials: the main parser reads fewer than 4,096
        // spheres itself, then takes three runs whole. Room is made at the first run; before,
        // none was, and each run's spheres were added by doubling (room for 1.3× or more).
        let text = big_text_after_materials(68_000, 20_000);
        assert!(text.contains("numMaterials 20003\n"));
        let first_run = split_points(&text, 4)[0].0;
        let read_by_main = text[..first_run].matches("Sphere").count();
        assert!(
            (1..SPHERES_BEFORE_RESERVE).contains(&read_by_main),
            "{read_by_main}"
        );
        RUNS_TAKEN.with(|taken| taken.set(0));
        let scene = parse_in_chunks(&text, &|_| {}, 0, 4).unwrap();
        assert_eq!(RUNS_TAKEN.with(std::cell::Cell::get), 3);
        assert_eq!(scene, sequential(&text).unwrap());
        let spare = scene.spheres.capacity() as f64 / 68_000.0;
        assert!(
            (1.0..1.25).contains(&spare),
            "four chunks: room for {spare}×"
        );
    }

    #[test]
    fn an_error_in_the_second_half_is_the_one_a_single_thread_finds() {
        let text = big_text(120_000);
        let at = text.len() * 3 / 4;
        let line = at + text[at..].find("radius 0.").unwrap();
        for (replace, with) in [
            ("radius 0.", "radius -0."),
            ("radius 0.", "radius x."),
            ("radius 0.", "}radius 0."),
        ] {
            let mut broken = text.clone();
            broken.replace_range(line..line + replace.len(), with);
            let split = parse_scene(&broken).unwrap_err();
            assert_eq!(split, sequential(&broken).unwrap_err(), "{with}");
            assert!(split.location.line > 80_000, "{split}");
        }
        // A material index out of range late in the file: reported at its own line.
        let mut broken = text.clone();
        let late = text.rfind("MaterialIndex 2").unwrap();
        broken.replace_range(late..late + 15, "MaterialIndex 9");
        let split = parse_scene(&broken).unwrap_err();
        assert_eq!(split, sequential(&broken).unwrap_err());
    }

    #[test]
    fn small_texts_parse_the_same_on_two_threads() {
        // The fuzz target's path: the split from 0 bytes, on the course scenes and on broken
        // texts, gives the one-thread scene or error.
        let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let mut texts: Vec<String> = (1..=7)
            .map(|n| std::fs::read_to_string(folder.join(format!("scene1_0{n}.txt"))).unwrap())
            .collect();
        let small = big_text(2_000);
        texts.push(small.replace("radius 0.5", "radius -0.5"));
        texts.push(small.replace("MaterialIndex 2", "MaterialIndex 7"));
        texts.push(small.clone());
        let mut split_parsed = 0;
        for text in &texts {
            let one_thread = sequential(text);
            assert_eq!(crate::scene::parse_scene_split_from(text, 0), one_thread);
            split_parsed += usize::from(split_point(text).is_some());
        }
        assert!(split_parsed >= 3, "{split_parsed} texts had a split point");
    }
}
