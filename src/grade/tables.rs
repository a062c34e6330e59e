//! The report for the course's own tools: `report.json` (every cell with its whole answer, as
//! `-compare_format json` gives it) and `report.csv` (a row per submission and image).

use std::fmt::Write as _;

use serde_json::{Value, json};

use super::mark::Outcome;
use super::report::{ClassReport, REPORT_FORMAT, short, status};

/// Version of `report.json`; raised when a field changes meaning or goes.
pub(super) const REPORT_JSON_VERSION: u32 = 1;

/// The report as one JSON document.
pub(super) fn json(class: &ClassReport) -> String {
    let columns = class.columns();
    let submissions: Vec<Value> = class
        .graded
        .iter()
        .map(|graded| {
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
        })
        .collect();
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
        "submissions": submissions,
    });
    let mut text = serde_json::to_string_pretty(&document).unwrap_or_default();
    text.push('\n');
    text
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

/// The report as CSV: a row per submission and image.
pub(super) fn csv(class: &ClassReport) -> String {
    let mut text = String::from(
        "submission,line,kind,file,found_as,status,pixels_differing,unexplained_pixels,deviations,short\n",
    );
    for graded in &class.graded {
        if let Some(why) = &graded.submission.skipped {
            let _ = writeln!(
                text,
                "{},,,,,skipped,,,,{}",
                field(&graded.submission.name),
                field(why)
            );
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
            text.push_str(&row.join(","));
            text.push('\n');
        }
    }
    text
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
