//! Grades a generated class with the release binary and checks its report against what each
//! student's program does; writes `docs/grading-speed.md`:
//!
//! ```sh
//! cargo build --release && cargo run --release --example grade_class [SUBMISSIONS] [OUT] [REPORT]
//! ```
//!
//! Each submission is a program of the student caster (`examples/support/student.rs`; one to
//! three behaviours of non-round values drawn from its seed, as in the generated corpus; every
//! fifth one the course's own program), its seven command lines' images written as TGA files.
//! REPORT keeps the class's report there (`cargo xtask report grading` screenshots it).
//! The whole `raytracer grade` command is timed, as a teacher runs it. Every cell of the report is
//! then judged against the program's behaviours (`examples/support/judge.rs`): a statement the
//! program does not make is wrong. SUBMISSIONS defaults to 100.

#[path = "support/judge.rs"]
mod judge;
#[path = "support/student.rs"]
mod student;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use judge::{Verdict, judge};
use student::{Draw, Program, draw_program, render};

/// The assignment's lines: scene, depth range, images (as `scenes/assignment1.commands` has them).
fn assignment_lines(assignment: &Path) -> Vec<(String, f64, f64, String, String)> {
    let text = std::fs::read_to_string(assignment).expect("the course's assignment file");
    text.lines()
        .filter(|line| line.starts_with("raytracer "))
        .map(|line| {
            let words: Vec<&str> = line.split_whitespace().collect();
            let at = |flag: &str| words.iter().position(|w| *w == flag).expect(flag);
            let depth = at("-depth");
            (
                words[at("-input") + 1].to_owned(),
                words[depth + 1].parse().expect("DMIN"),
                words[depth + 2].parse().expect("DMAX"),
                words[at("-output") + 1].to_owned(),
                words[depth + 3].to_owned(),
            )
        })
        .collect()
}

fn main() {
    let mut arguments = std::env::args().skip(1);
    let count: u64 = arguments
        .next()
        .map_or(100, |n| n.parse().expect("SUBMISSIONS"));
    let out = arguments
        .next()
        .unwrap_or_else(|| "docs/grading-speed.md".to_owned());
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let binary = root.join("target/release/raytracer");
    let assignment = root.join("scenes/assignment1.commands");
    let lines = assignment_lines(&assignment);
    let work = tempfile::tempdir().expect("a temporary folder");
    // The command runs in the work folder on a copy of the assignment and its scenes, so the
    // report names them as a teacher's would (`scenes/assignment1.commands`, `class`).
    std::fs::create_dir_all(work.path().join("scenes")).expect("a scenes folder");
    std::fs::copy(&assignment, work.path().join("scenes/assignment1.commands")).expect("a copy");
    for (scene, ..) in &lines {
        std::fs::copy(
            root.join("scenes").join(scene),
            work.path().join("scenes").join(scene),
        )
        .expect("a copy of a scene");
    }
    let class = work.path().join("class");
    let report_folder = arguments.next().map_or_else(
        || work.path().join("report"),
        |folder| std::path::absolute(folder).expect("the report's folder"),
    );

    let mut programs: BTreeMap<String, Program> = BTreeMap::new();
    let making = Instant::now();
    for seed in 0..count {
        let program = if seed % 5 == 4 {
            Program::course()
        } else {
            draw_program(&mut Draw::new(seed), false)
        };
        let name = format!("student-{seed:03}");
        let folder = class.join(&name);
        std::fs::create_dir_all(&folder).expect("a submission folder");
        for (scene, dmin, dmax, colour_name, depth_name) in &lines {
            let scene = raytracer::scene::load_scene(&root.join("scenes").join(scene))
                .expect("a course scene");
            let (colour, depth) = render(&program, &scene, 200, 200, *dmin, *dmax);
            colour.save(folder.join(colour_name)).expect("a TGA");
            depth.save(folder.join(depth_name)).expect("a TGA");
        }
        programs.insert(name, program);
    }
    eprintln!(
        "made {count} submissions in {:.1} s",
        making.elapsed().as_secs_f64()
    );

    let started = Instant::now();
    let output = std::process::Command::new(&binary)
        .current_dir(work.path())
        .args(["grade", "scenes/assignment1.commands", "class"])
        .arg("-o")
        .arg(&report_folder)
        .output()
        .expect("the release binary (cargo build --release)");
    let seconds = started.elapsed().as_secs_f64();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let report: serde_json::Value = serde_json::from_slice(
        &std::fs::read(report_folder.join("report.json")).expect("report.json"),
    )
    .expect("JSON");

    let mut verdicts: BTreeMap<Verdict, usize> = BTreeMap::new();
    let mut wrong = Vec::new();
    let mut cells = 0;
    for submission in report["submissions"].as_array().expect("submissions") {
        let name = submission["name"].as_str().unwrap_or_default();
        let truth = programs[name].truth();
        for cell in submission["images"].as_array().expect("images") {
            cells += 1;
            let answer = &cell["answer"];
            let names = |list: &serde_json::Value| -> Vec<String> {
                list.as_array()
                    .map(|l| {
                        l.iter()
                            .map(|s| s["name"].as_str().unwrap_or_default().to_owned())
                            .collect()
                    })
                    .unwrap_or_default()
            };
            let stated = [names(&answer["statements"]), names(&answer["partial"])].concat();
            let alternatives: Vec<Vec<String>> = answer["alternatives"]
                .as_array()
                .map(|a| a.iter().map(names).collect())
                .unwrap_or_default();
            let verdict = judge(
                cell["status"] == "match",
                &stated,
                &alternatives,
                answer["unexplained_pixels"].as_u64().unwrap_or(u64::MAX),
                200 * 200,
                &truth,
            );
            if verdict == Verdict::Wrong || cell["status"] != "match" && cell["status"] != "differs"
            {
                wrong.push(format!(
                    "{name} {}: {} (truth {truth:?})",
                    cell["file"], cell["short"]
                ));
            }
            *verdicts.entry(verdict).or_default() += 1;
        }
    }
    let get = |v: Verdict| verdicts.get(&v).copied().unwrap_or(0);
    let mut text = String::new();
    let _ = writeln!(
        text,
        "# Grading a class: speed and correctness\n\n\
         Generated by `cargo build --release && cargo run --release --example grade_class {count}`\n\
         (`examples/grade_class.rs`): {count} submissions of the student caster, every fifth the \
         course's own program, the others with one to three behaviours of non-round values; the \
         whole `raytracer grade scenes/assignment1.commands CLASS -o REPORT` command timed, then each \
         cell of its report judged against what the program does.\n"
    );
    let _ = writeln!(text, "| | |\n|---|---|");
    let _ = writeln!(
        text,
        "| submissions × images | {count} × {} = {cells} |",
        2 * lines.len()
    );
    let _ = writeln!(
        text,
        "| threads | {} |",
        std::thread::available_parallelism().map_or(1, std::num::NonZero::get)
    );
    let _ = writeln!(text, "| whole command | {seconds:.1} s |");
    let _ = writeln!(
        text,
        "| distinct comparisons (a line's two images together) | {} |",
        report["distinct_comparisons"]
    );
    let _ = writeln!(text, "| match | {} |", get(Verdict::Match));
    let _ = writeln!(
        text,
        "| differs, explained (≤ 1% of pixels left) | {} |",
        get(Verdict::Explained)
    );
    let _ = writeln!(
        text,
        "| differs, explained in part | {} |",
        get(Verdict::Partial)
    );
    let _ = writeln!(
        text,
        "| **a statement the program does not make** | **{}** |",
        get(Verdict::Wrong)
    );
    if !wrong.is_empty() {
        let _ = writeln!(text, "\nWrong or unmarked cells:\n");
        for line in &wrong {
            let _ = writeln!(text, "- {line}");
        }
    }
    std::fs::write(&out, &text).expect("the report");
    print!("{text}");
}
