//! The source tree's house rules, checked on the files themselves: imports run downward through
//! the layers (geometry, scene, render at the bottom; the viewer at the top), no two modules
//! import each other, no file (of `src/`, `tests/`, `examples/`, `benches/`, the fuzz targets;
//! unit tests included) is longer than 500 lines and the viewer's `mod.rs` only declares (100);
//! the viewer's coordinator, `ViewerApp`, has its `impl` in its own file (the files that still
//! add to it listed, the list only shrinking); what differs by operating system is named in
//! `src/platform/` alone; a request's outputs are written out only where the flag table, their
//! list and the run that makes them are; the dead-code lint is never silenced for the whole crate;
//! every shared command-line case runs against both the native binary and the Windows `.exe`;
//! inside `src/app` and `src/render` no file imports an item from a module above it (a module's
//! `mod.rs` declares and re-exports; its children import each other by their own names); what a
//! browser page does otherwise is switched (`target_arch = "wasm32"`) only in `src/platform/` and
//! the viewer's seams, with the switches still elsewhere counted down.

#[path = "common/source_tree.rs"]
mod source_tree;

use source_tree::{
    crate_references, expanded_paths, files_under, module_of, module_path, named_paths,
    relative_name, source_files, used_modules, without_tests,
};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The layers, bottom first. A module may use its own layer and the layers before it; `oracle`
/// (test and study support) may use the core, and nothing but tests may use it.
const LAYERS: [&str; 12] = [
    "platform", "geometry", "scene", "render", "oracle", "explore", "output", "compare", "cli",
    "export", "grade", "app",
];

#[test]
fn the_checks_read_test_declarations_and_grouped_imports() {
    // A `mod tests;` declaration is no test block: the re-exports after it are code.
    let text = "mod a;\n#[cfg(test)]\nmod tests;\npub use a::X;\n";
    assert_eq!(without_tests(text), text);
    let text = "fn f() {}\n#[cfg(test)]\nmod tests {\n    use crate::app::X;\n}\n";
    assert_eq!(without_tests(text), "fn f() {}\n");
    // Grouped imports name every module in the group.
    let found = crate_references(
        "use crate::{\n    render::{View, Frame},\n    app::ViewerApp,\n};",
        1,
    );
    let expected: BTreeSet<Vec<String>> = [vec!["render".to_owned()], vec!["app".to_owned()]]
        .into_iter()
        .collect();
    assert_eq!(found, expected);
}

#[test]
fn imports_run_downward_through_the_layers() {
    let layer_of = |name: &str| LAYERS.iter().position(|layer| *layer == name);
    let mut upward = Vec::new();
    for file in source_files() {
        let module = module_path(&file);
        let Some(own) = module.first().and_then(|top| layer_of(top)) else {
            continue; // lib.rs, main.rs
        };
        let text = std::fs::read_to_string(&file).unwrap();
        for reference in crate_references(without_tests(&text), 2) {
            let Some(used) = layer_of(&reference[0]) else {
                continue;
            };
            let oracle = layer_of("oracle").unwrap();
            // The oracle of mistaken images takes the mistakes' names from the comparison's
            // vocabulary (`compare::mistake`, no code of the fit it checks).
            let vocabulary = own == oracle && reference == ["compare", "mistake"];
            let allowed = if used == oracle {
                own == oracle
            } else {
                used <= own || vocabulary
            };
            if !allowed {
                upward.push(format!("{} uses crate::{}", file.display(), reference[0]));
            }
        }
    }
    assert!(
        upward.is_empty(),
        "imports against the layers:\n{upward:#?}"
    );
}

#[test]
fn no_import_circles_between_modules() {
    let files = source_files();
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_path(f)).collect();
    // Module → the modules it uses (not its own ancestors or descendants: a folder's mod.rs
    // declaring and re-exporting its children is not an import).
    let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    for file in &files {
        let own = module_path(file);
        let text = std::fs::read_to_string(file).unwrap();
        for used in used_modules(without_tests(&text), &own, &modules) {
            let related = used.starts_with(&own) || own.starts_with(&used);
            if !related {
                edges.entry(own.clone()).or_default().insert(used);
            }
        }
    }
    // Depth-first search for a path back to where it started.
    let mut circles = Vec::new();
    for start in edges.keys() {
        let mut stack = vec![(start.clone(), vec![start.clone()])];
        let mut seen = BTreeSet::new();
        while let Some((at, path)) = stack.pop() {
            for next in edges.get(&at).into_iter().flatten() {
                if next == start {
                    let names: Vec<String> = path.iter().map(|m| m.join("::")).collect();
                    circles.push(format!("{} → {}", names.join(" → "), start.join("::")));
                } else if seen.insert(next.clone()) {
                    let mut longer = path.clone();
                    longer.push(next.clone());
                    stack.push((next.clone(), longer));
                }
            }
        }
    }
    assert!(circles.is_empty(), "import circles:\n{circles:#?}");
}

#[test]
fn files_stay_short_and_the_viewers_mod_only_declares() {
    let mut long = Vec::new();
    for file in files_under(&["src", "tests", "examples", "benches", "fuzz/fuzz_targets"]) {
        let text = std::fs::read_to_string(&file).unwrap();
        // Every file, its unit tests included; the viewer's `mod.rs` declares and re-exports.
        let (lines, limit) = if file.ends_with("src/app/mod.rs") {
            (without_tests(&text).lines().count(), 100)
        } else {
            (text.lines().count(), 500)
        };
        if lines > limit {
            long.push(format!("{}: {lines} lines (limit {limit})", file.display()));
        }
    }
    assert!(long.is_empty(), "files over their limit:\n{long:#?}");
}

/// What names an operating system's own interface: its standard-library extensions (however
/// imported), the crates that serve its signals, console events and system calls, the signals
/// themselves, and conditions on the target system.
const OPERATING_SYSTEM_NAMES: [&str; 19] = [
    "std::os",
    "os::unix",
    "os::windows",
    "os::fd",
    "signal_hook",
    "ctrlc",
    "rustix",
    "libc::",
    "windows_sys",
    "winapi",
    "same_file::",
    "SIGINT",
    "SIGTERM",
    "SIGHUP",
    "SIGXFSZ",
    "(unix",
    "(windows",
    "target_os",
    "target_family",
];

#[test]
fn only_the_platform_layer_names_an_operating_system() {
    let mut found = Vec::new();
    for file in source_files() {
        let module = module_path(&file);
        if module.first().is_some_and(|top| top == "platform") {
            continue;
        }
        let text = std::fs::read_to_string(&file).unwrap();
        for (number, line) in text.lines().enumerate() {
            let code = line.trim_start();
            // Comments may speak of systems. The one allowed condition: the binary's allocator
            // follows its target-specific dependency (Cargo.toml: not on macOS).
            if code.starts_with("//") || code.contains("feature = \"mimalloc\"") {
                continue;
            }
            for name in OPERATING_SYSTEM_NAMES {
                if code.contains(name) {
                    found.push(format!("{}:{}: {name}", file.display(), number + 1));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "operating-system names outside src/platform/:\n{found:#?}"
    );
}

/// The files where a request's outputs are written out: the flag table (with each output's
/// formats), the list of outputs, and the run that makes each file (and the command line's unit
/// tests).
const OUTPUT_FILES: [&str; 4] = [
    "src/cli/flags.rs",
    "src/cli/outputs.rs",
    "src/cli/run.rs",
    "src/cli/tests.rs",
];

#[test]
fn a_requests_outputs_are_listed_in_one_place() {
    // The outputs beyond the course's `-output` and `-depth` stand for any new one: a new output
    // flag touches the flag table, the outputs' list and the run, nothing else.
    let mut found = Vec::new();
    let mut named = 0;
    for file in source_files() {
        let relative = relative_name(&file);
        let text = std::fs::read_to_string(&file).unwrap();
        for (number, line) in text.lines().enumerate() {
            for name in [
                "Flag::Depth16",
                "Flag::DepthRaw",
                "outputs.depth16",
                "outputs.depth_raw",
            ] {
                if line.contains(name) {
                    if OUTPUT_FILES.contains(&relative.as_str()) {
                        named += 1;
                    } else {
                        found.push(format!("{relative}:{}: {name}", number + 1));
                    }
                }
            }
        }
    }
    assert!(
        named >= 4,
        "the output flags were found only {named} times in their own files"
    );
    assert!(
        found.is_empty(),
        "outputs written out elsewhere:\n{found:#?}"
    );
}

#[test]
fn the_dead_code_lint_is_never_silenced_for_the_whole_crate() {
    // Viewer-only code is built only with the viewer (`app`, `export`), so the lint speaks for
    // the build without it too.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for file in ["src/lib.rs", "src/main.rs"] {
        let text = std::fs::read_to_string(root.join(file)).unwrap();
        let silenced: Vec<&str> = text
            .lines()
            .filter(|line| line.trim_start().starts_with("#![") && line.contains("dead_code"))
            .collect();
        assert!(silenced.is_empty(), "{file}: {silenced:?}");
    }
}

#[test]
fn every_shared_command_line_case_runs_against_both_programs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |path: &str| std::fs::read_to_string(root.join(path)).unwrap();
    let cases: Vec<String> = read("tests/common/cli_cases.rs")
        .lines()
        .filter_map(|line| line.strip_prefix("pub(crate) fn "))
        .map(|rest| rest[..rest.find('(').unwrap()].to_owned())
        .collect();
    assert!(cases.len() >= 5, "found {} cases", cases.len());
    for (runner, program) in [
        ("tests/cli.rs", "Program::native()"),
        ("tests/windows_exe.rs", "Program::windows()"),
    ] {
        let text = read(runner);
        for case in &cases {
            let call = format!("cli_cases::{case}(&{program})");
            assert!(
                text.contains(&call),
                "{runner} does not run {case}: no `{call}`"
            );
        }
    }
}

#[test]
fn the_coordinators_impl_is_in_its_own_file_alone() {
    let mut outside = Vec::new();
    for file in files_under(&["src"]) {
        let text = std::fs::read_to_string(&file).unwrap();
        let name = relative_name(&file);
        // `impl ViewerApp`, `impl super::viewer::ViewerApp`, `impl eframe::App for ViewerApp`.
        let has_impl = without_tests(&text)
            .lines()
            .any(|line| line.trim_start().starts_with("impl") && line.contains("ViewerApp"));
        if has_impl && name != "src/app/viewer.rs" {
            outside.push(name);
        }
    }
    assert!(
        outside.is_empty(),
        "impl blocks of ViewerApp outside src/app/viewer.rs (a feature owns its behaviour on \
         its own state, a seam is a type of its own that the coordinator calls; the coordinator \
         routes):\n{outside:#?}"
    );
}

#[test]
fn no_file_in_the_viewer_or_the_renderer_imports_from_a_module_above_it() {
    let files = source_files();
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_path(f)).collect();
    let mut upward = Vec::new();
    for file in &files {
        let own = module_path(file);
        let in_scope = matches!(own.first().map(String::as_str), Some("app" | "render"));
        // A unit-test file (`*_tests.rs`) is its module's `tests`, not a module of the tree.
        if !in_scope || own.last().is_some_and(|name| name.ends_with("_tests")) {
            continue;
        }
        let text = std::fs::read_to_string(file).unwrap();
        for path in named_paths(without_tests(&text), &own) {
            // The longest prefix that is a module; an item follows it.
            let module = module_of(&path, &modules);
            let names_an_item = path.len() > module.len();
            let above = !module.is_empty() && module.len() < own.len() && own.starts_with(&module);
            if names_an_item && above {
                upward.push(format!("{}: {}", file.display(), path.join("::")));
            }
        }
    }
    assert!(
        upward.is_empty(),
        "imports of an item from a module above the file:\n{upward:#?}"
    );
}

#[test]
fn the_upward_import_check_reads_groups_and_globs() {
    let none: [String; 0] = [];
    let paths = expanded_paths(&none, "a::{b, c::{d, e}, f::*};");
    let names: Vec<String> = paths.iter().map(|p| p.join("::")).collect();
    assert_eq!(names, ["a::b", "a::c::d", "a::c::e", "a::f::*"]);
}

/// Where a browser page's differences may be switched on `target_arch = "wasm32"`: the platform
/// layer, the viewer's page and desktop seams, the seam's choice and what a seam asks, how the
/// viewer starts, and the program's entry.
const SEAMS: [&str; 7] = [
    "src/platform/",
    "src/app/web",
    "src/app/desktop.rs",
    "src/app/seam.rs",
    "src/app/asked.rs",
    "src/app/start/",
    "src/main.rs",
];

/// The switches still outside the seams, file by file: in `src/app/mod.rs` the two seams'
/// declarations; in the coordinator (`src/app/viewer.rs`) `as_any_mut`, which eframe's `App`
/// trait has only in a page (the seam it holds is switched in `src/app/seam.rs`). A count may
/// only fall:
/// a file with fewer must have its count lowered here.
const SWITCHES_LEFT: [(&str, usize); 2] = [("src/app/mod.rs", 2), ("src/app/viewer.rs", 1)];

#[test]
fn a_browser_pages_differences_are_switched_in_the_seams() {
    let mut wrong = Vec::new();
    for file in source_files() {
        let name = relative_name(&file);
        if SEAMS.iter().any(|seam| name.starts_with(seam)) {
            continue;
        }
        let text = std::fs::read_to_string(&file).unwrap();
        let count = text.matches("target_arch = \"wasm32\"").count();
        let allowed = SWITCHES_LEFT
            .iter()
            .find(|(left, _)| *left == name)
            .map_or(0, |(_, left)| *left);
        if count != allowed {
            wrong.push(format!("{name}: {count} switches, {allowed} allowed"));
        }
    }
    assert!(
        wrong.is_empty(),
        "switches on wasm32 outside the seams (move them there; a count that fell is lowered in \
         SWITCHES_LEFT):\n{wrong:#?}"
    );
}

#[test]
fn every_test_file_runs_in_exactly_one_test_binary() {
    // Cargo.toml turns cargo's discovery of test files off (`autotests = false`) and lists the
    // test binaries: a suite (tests/suites/NAME.rs) gathers several files as modules, the rest
    // stand alone. A file in neither would never run; a file in two would run twice.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let manifest = std::fs::read_to_string(root.join("Cargo.toml")).unwrap();
    assert!(
        manifest.contains("\nautotests = false\n"),
        "Cargo.toml: autotests"
    );
    let mut runs: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut targets = 0;
    for block in manifest.split("\n[[test]]\n").skip(1) {
        let path = block
            .lines()
            .find_map(|line| line.strip_prefix("path = \""))
            .and_then(|rest| rest.strip_suffix('"'))
            .unwrap_or_else(|| panic!("a [[test]] without a path: {block}"));
        assert!(
            root.join(path).is_file(),
            "Cargo.toml lists {path}: no such file"
        );
        targets += 1;
        let Some(suite) = path.strip_prefix("tests/suites/") else {
            runs.entry(path.to_owned())
                .or_default()
                .push(path.to_owned());
            continue;
        };
        let text = std::fs::read_to_string(root.join(path)).unwrap();
        let mut lines = text.lines().filter(|line| !line.starts_with("//"));
        while let Some(line) = lines.next() {
            let Some(file) = line
                .strip_prefix("#[path = \"../")
                .and_then(|rest| rest.strip_suffix(".rs\"]"))
            else {
                continue;
            };
            assert_eq!(
                lines.next(),
                Some(format!("mod {file};").as_str()),
                "{suite}: the module of {file}.rs is named as its file"
            );
            runs.entry(format!("tests/{file}.rs"))
                .or_default()
                .push(path.to_owned());
        }
    }
    assert!(targets >= 2, "Cargo.toml: no [[test]] list read");
    for entry in std::fs::read_dir(root.join("tests")).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if Path::new(&name).extension().is_some_and(|e| e == "rs") {
            let file = format!("tests/{name}");
            let binaries = runs.remove(&file).unwrap_or_default();
            assert_eq!(binaries.len(), 1, "{file} runs in {binaries:?}");
        }
    }
    assert!(runs.is_empty(), "listed but not in tests/: {runs:?}");
}
