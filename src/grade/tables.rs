//! The report for the course's own tools: `report.json` (every cell with its whole answer, as
//! `-compare_format json` gives it) and `report.csv` (a row per submission and image).

use std::io::Write;

use serde_json::{Value, json};

use super::mark::Outcome;
use super::report::{ClassReport, Graded, REPORT_FORMAT, short, status};

/// Version of `report.json`; raised when a field changes meaning or goes.
pub(super) const REPORT_JSON_VERSION: u32 = 1;

/// One submission's entry of `report.json`.
fn submission_json(class: &ClassReport, graded: &Graded) -> Value {
    let images: Vec<Value> = graded
        .marks
        .iter()
        .map(|(index, mark)| {
            let mut cell = json!({
                "line": class.tasks[*index].line_number,
                "kind": mark.kind.word(),
                "file": mark.wanted.display().to_string(),
                "found_as": mark.renamed,
                "status": status(mark),
                "short": short(mark),
            });
            match &mark.outcome {
                Outcome::Compared(answer) => {
                    if let Some((_, image)) = mark.answer() {
                        cell["pixels_differing"] = json!(image.pixels_differing);
                        cell["unexplained_pixels"] = json!(image.unexplained_pixels);
                    }
                    cell["answer"] = answer.json.clone();
                }
                Outcome::Unreadable(why) => cell["why"] = json!(why),
                Outcome::WrongSize { found, expected } => {
                    cell["size"] = json!([found.0, found.1]);
                    cell["expected_size"] = json!([expected.0, expected.1]);
                }
                Outcome::Missing => {}
            }
            cell
        })
        .collect();
    json!({
        "name": graded.submission.name,
        "skipped": graded.submission.skipped,
        "page": graded.page,
        "matching": graded.matching(),
        "deviations": graded.words(),
        "images": images,
    })
}

/// Stands in the document for the submissions, which are written one at a time.
const SUBMISSIONS_HERE: &str = "\u{0}submissions\u{0}";

/// Writes the report as one JSON document to `out`: the class's fields, then each submission
/// made and written in turn, so that a class's whole document is never held in memory.
pub(super) fn write_json(class: &ClassReport, out: &mut impl Write) -> std::io::Result<()> {
    let columns = class.columns();
    let document = json!({
        "format": REPORT_FORMAT,
        "version": REPORT_JSON_VERSION,
        "assignment": class.assignment,
        "lines": class.tasks.iter().map(|t| json!({"line": t.line_number, "command": t.line})).collect::<Vec<_>>(),
        "images": columns.iter().map(|(_, kind, name)| json!({"file": name, "kind": kind.word()})).collect::<Vec<_>>(),
        "submissions_graded": class.graded_count(),
        "deviation_totals": class.deviation_totals(),
        "status_totals": class.status_totals(),
        "distinct_comparisons": class.distinct_images,
        "marked_at_once": class.threads,
        "memory_budget_mb": class.memory_budget_bytes.map(|bytes| (bytes / 100_000) as f64 / 10.0),
        "submissions": SUBMISSIONS_HERE,
    });
    let text = serde_json::to_string_pretty(&document).map_err(std::io::Error::other)?;
    let placeholder = serde_json::to_string(SUBMISSIONS_HERE).map_err(std::io::Error::other)?;
    let (before, after) = text
        .split_once(&placeholder)
        .ok_or_else(|| std::io::Error::other("the submissions' place in report.json"))?;
    out.write_all(before.as_bytes())?;
    if class.graded.is_empty() {
        out.write_all(b"[]")?;
    } else {
        out.write_all(b"[")?;
        for (number, graded) in class.graded.iter().enumerate() {
            let entry = serde_json::to_string_pretty(&submission_json(class, graded))
                .map_err(std::io::Error::other)?;
            out.write_all(if number == 0 { b"\n" } else { b",\n" })?;
            // One level deeper than the document's fields: four spaces.
            for (line_number, line) in entry.lines().enumerate() {
                if line_number > 0 {
                    out.write_all(b"\n")?;
                }
                out.write_all(b"    ")?;
                out.write_all(line.as_bytes())?;
            }
        }
        out.write_all(b"\n  ]")?;
    }
    out.write_all(after.as_bytes())?;
    out.write_all(b"\n")
}

/// A CSV field: quoted where it holds a comma, a quote or a line break; a leading `=`, `+`, `-`,
/// `@`, TAB or carriage return is prefixed with `'` so a spreadsheet does not run it as a formula.
fn field(text: &str) -> String {
    let text = if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{text}")
    } else {
        text.to_owned()
    };
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text
    }
}

/// Writes the report as CSV to `out`: a row per submission and image, each written as made.
pub(super) fn write_csv(class: &ClassReport, out: &mut impl Write) -> std::io::Result<()> {
    out.write_all(
        b"submission,line,kind,file,found_as,status,pixels_differing,unexplained_pixels,deviations,short\n",
    )?;
    for graded in &class.graded {
        if let Some(why) = &graded.submission.skipped {
            writeln!(
                out,
                "{},,,,,skipped,,,,{}",
                field(&graded.submission.name),
                field(why)
            )?;
            continue;
        }
        for (index, mark) in &graded.marks {
            let (differing, unexplained, words) = match mark.answer() {
                Some((answer, image)) => (
                    image.pixels_differing.to_string(),
                    image.unexplained_pixels.to_string(),
                    answer
                        .statements_on(mark.kind)
                        .map(|s| s.word.as_str())
                        .collect::<Vec<_>>()
                        .join(" "),
                ),
                None => (String::new(), String::new(), String::new()),
            };
            let row = [
                field(&graded.submission.name),
                class.tasks[*index].line_number.to_string(),
                mark.kind.word().to_owned(),
                field(&mark.wanted.display().to_string()),
                field(mark.renamed.as_deref().unwrap_or("")),
                field(status(mark)),
                differing,
                unexplained,
                field(&words),
                field(&short(mark)),
            ];
            out.write_all(row.join(",").as_bytes())?;
            out.write_all(b"\n")?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::field;

    #[test]
    fn a_field_is_never_a_formula_and_stays_one_field() {
        assert_eq!(field("alice"), "alice");
        assert_eq!(field("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
        assert_eq!(field("+1"), "'+1");
        assert_eq!(field("-2"), "'-2");
        assert_eq!(field("@SUM(A1)"), "'@SUM(A1)");
        assert_eq!(field("a,b"), "\"a,b\"");
        assert_eq!(field("two\nlines"), "\"two\nlines\"");
    }
}
