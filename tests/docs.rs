//! The documentation cannot drift from what backs it:
//! * every table in README.md and in the pages of docs/ marked `<!-- from docs/NAME.md -->` holds
//!   rows that are, verbatim, rows of that generated report (the reports are written by committed commands), and every
//!   code block so marked holds lines of it;
//! * every row of docs/robustness.md cites tests that exist (or says "same" for the row above);
//! * the README is a front door: at most 250 lines, the download its first section;
//! * the README's times of the last CI run are those of docs/ci-steps.txt.

#[path = "common/source_tree.rs"]
#[allow(dead_code)] // the file walk alone
mod source_tree;

use source_tree::rust_files;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn read(relative: &str) -> String {
    std::fs::read_to_string(root().join(relative)).unwrap_or_else(|e| panic!("{relative}: {e}"))
}

/// The table rows (lines starting with `|`, not the `|---|` separators) from `start` on, up to
/// the first line that is not part of the table.
fn table_rows<'a>(lines: &[&'a str], start: usize) -> Vec<&'a str> {
    lines[start..]
        .iter()
        .skip_while(|line| !line.starts_with('|'))
        .take_while(|line| line.starts_with('|'))
        .filter(|line| !line.starts_with("|---"))
        .copied()
        .collect()
}

/// README.md and the pages of docs/ that quote a report.
fn pages_with_markers() -> Vec<String> {
    let mut pages = vec!["README.md".to_owned()];
    let mut docs: Vec<String> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| Path::new(name).extension().is_some_and(|e| e == "md"))
        .map(|name| format!("docs/{name}"))
        .collect();
    docs.sort();
    pages.extend(docs);
    pages
}

#[test]
fn marked_tables_equal_the_generated_reports() {
    let mut checked = 0;
    for page in pages_with_markers() {
        checked += check_marked_tables(&page);
    }
    assert!(checked >= 40, "only {checked} rows are marked as generated");
}

/// Checks the marked tables and blocks of `page`; returns the rows checked.
fn check_marked_tables(page: &str) -> usize {
    let readme = read(page);
    let lines: Vec<&str> = readme.lines().collect();
    let mut checked = 0;
    for (index, line) in lines.iter().enumerate() {
        let Some(source) = line
            .trim()
            .strip_prefix("<!-- from ")
            .and_then(|rest| rest.strip_suffix(" -->"))
        else {
            continue;
        };
        let report = read(source);
        let report_lines: Vec<&str> = report.lines().map(str::trim_end).collect();
        // A code block: each of its lines is a line of the source.
        if lines
            .get(index + 1)
            .is_some_and(|next| next.starts_with("```"))
        {
            let block: Vec<&str> = lines[index + 2..]
                .iter()
                .take_while(|line| !line.starts_with("```"))
                .copied()
                .collect();
            assert!(
                !block.is_empty(),
                "the block after line {} is empty",
                index + 1
            );
            for line in block {
                assert!(
                    report_lines.contains(&line.trim_end()),
                    "{page} line not in {source}:\n{line}"
                );
                checked += 1;
            }
            continue;
        }
        let rows = table_rows(&lines, index + 1);
        assert!(
            rows.len() > 1,
            "the table after line {} is empty",
            index + 1
        );
        for row in rows {
            assert!(
                report_lines.contains(&row.trim_end()),
                "{page} row not in {source}:\n{row}"
            );
            checked += 1;
        }
    }
    checked
}

#[test]
fn every_robustness_row_cites_tests_that_exist() {
    let mut sources = Vec::new();
    rust_files(&root().join("src"), &mut sources);
    rust_files(&root().join("tests"), &mut sources);
    // The names of the test functions: `fn name(` after `#[test]` (and its other attributes,
    // such as `#[ignore = …]`).
    let mut tests = std::collections::BTreeSet::new();
    for path in &sources {
        let text = std::fs::read_to_string(path).unwrap();
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        for (at, _) in lines.iter().enumerate().filter(|(_, l)| **l == "#[test]") {
            let function = lines[at + 1..].iter().find(|l| !l.starts_with("#["));
            if let Some(rest) = function.and_then(|l| l.strip_prefix("fn ")) {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                tests.insert(name);
            }
        }
    }
    let exists = |name: &str| tests.contains(name);
    let robustness = read("docs/robustness.md");
    let mut rows = 0;
    // Rows of the tables whose header has a "checked by" column.
    let mut in_checked_table = false;
    let mut previous_is_row = false;
    for line in robustness.lines() {
        let is_row = line.starts_with('|');
        if is_row && !previous_is_row {
            in_checked_table = line.contains("checked by");
        }
        previous_is_row = is_row;
        if !is_row || !in_checked_table || line.starts_with("|---") || line.contains("checked by") {
            continue;
        }
        let cells: Vec<&str> = line.trim_matches('|').split(" | ").collect();
        let cited = cells.last().unwrap().trim();
        let names: Vec<&str> = cited.split('`').skip(1).step_by(2).collect();
        if names.is_empty() {
            assert!(cited.starts_with("same"), "a row cites no test:\n{line}");
            continue;
        }
        for name in names {
            // A chore that CI runs checks what no test function can (an archive unpacked and
            // used): it must exist.
            if let Some(chore) = name.strip_prefix("cargo xtask ") {
                let chore = chore.split(' ').next().unwrap();
                assert!(
                    root().join(format!("xtask/chores/{chore}.sh")).is_file(),
                    "no chore `{chore}` for the row:\n{line}"
                );
                continue;
            }
            let function = name.rsplit("::").next().unwrap().trim_start_matches('…');
            assert!(
                exists(function),
                "no test `{function}` for the row:\n{line}"
            );
        }
        rows += 1;
    }
    assert!(rows >= 40, "only {rows} rows");
}

/// The README is the front door a newcomer reads: at most [`README_MOST_LINES`] lines, its first
/// section the download; the rest is a link away (docs/README.md lists every page).
#[test]
fn the_readme_is_short_and_starts_with_the_download() {
    let readme = read("README.md");
    let lines = readme.lines().count();
    assert!(
        lines <= README_MOST_LINES,
        "README.md has {lines} lines, more than {README_MOST_LINES}"
    );
    let first_section = readme.lines().find(|line| line.starts_with("## "));
    assert_eq!(first_section, Some("## Get it"));
    assert!(readme.contains("](docs/README.md)"));
}

/// The most lines the README may have.
const README_MOST_LINES: usize = 250;

/// The seconds `.ci/run` printed for `step` (`ci-step: N s: STEP`, or `ci-total: N s` for
/// "total") in docs/ci-steps.txt.
fn ci_seconds(steps: &str, step: &str) -> u64 {
    steps
        .lines()
        .find_map(|line| {
            let rest = if step == "total" {
                line.strip_prefix("ci-total: ")?.strip_suffix(" s")?
            } else {
                line.strip_prefix("ci-step: ")?
                    .strip_suffix(&format!(" s: {step}"))?
            };
            rest.parse().ok()
        })
        .unwrap_or_else(|| panic!("docs/ci-steps.txt has no {step}"))
}

/// The README's sentence on the last fresh-clone run of CI gives the test command's time and
/// CI's, each in minutes and seconds: the seconds are docs/ci-steps.txt's, the minutes rounded
/// from them, and the commit the run was made on is named there.
#[test]
fn the_readmes_ci_times_are_those_of_the_ci_steps_it_cites() {
    let steps = read("docs/ci-steps.txt");
    assert!(
        steps.starts_with("# .ci/run on a fresh clone of "),
        "docs/ci-steps.txt names the commit it ran on: {}",
        steps.lines().next().unwrap_or("")
    );
    let readme = read("README.md").replace('\n', " ");
    let sentence = readme
        .split("In the last fresh-clone run of CI")
        .nth(1)
        .and_then(|rest| rest.split("docs/ci-steps.txt").next())
        .expect("the README's sentence on the last CI run, citing docs/ci-steps.txt");
    let figures: Vec<u64> = sentence
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|word| word.parse().ok())
        .filter(|&n| n != 2) // "2 cores"
        .collect();
    let test_s = ci_seconds(&steps, "cargo xtask test");
    let total_s = ci_seconds(&steps, "total");
    let minutes = |s: u64| (s + 30) / 60;
    assert_eq!(
        figures,
        [minutes(test_s), test_s, minutes(total_s), total_s],
        "the README says {sentence:?}; docs/ci-steps.txt says {test_s} s and {total_s} s"
    );
}
