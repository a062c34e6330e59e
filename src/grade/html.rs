//! The report's HTML: the class table (`index.html`, sortable by any column, with the class's
//! totals) and a page per submission. Static files that work from the file system, with no
//! server and no network: the style and the sorting script are in the page. Every name from a
//! submission is escaped.

use std::fmt::Write as _;

use super::mark::{ImageKind, Mark, Outcome};
use super::report::{ClassReport, Graded, exact_image, short, status};
use crate::output::shell::shell_quote_path;

/// Characters that reorder the text around them (embeddings, overrides, isolates and marks):
/// in a name from a submission each is shown as its code (`alice<U+202E>gnp.exe`), never
/// obeyed, so that `alice\u{202E}gnp.exe` does not read as `aliceexe.png`.
fn is_direction_control(c: char) -> bool {
    matches!(
        c,
        '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}'
    )
}

/// `text` with the characters HTML gives a meaning escaped, and those that reorder text shown
/// by their codes.
pub(crate) fn escape(text: &str) -> String {
    let mut escaped = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            c if is_direction_control(c) => {
                let _ = write!(escaped, "&lt;U+{:04X}&gt;", u32::from(c));
            }
            '&' => escaped.push_str("&amp;"),
            '<' => escaped.push_str("&lt;"),
            '>' => escaped.push_str("&gt;"),
            '"' => escaped.push_str("&quot;"),
            '\'' => escaped.push_str("&#39;"),
            c => escaped.push(c),
        }
    }
    escaped
}

const STYLE: &str = "body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222}\
table{border-collapse:collapse}th,td{border:1px solid #ccc;padding:3px 6px;text-align:left;\
vertical-align:top}th{background:#eee;cursor:pointer;user-select:none}\
th[aria-sort=ascending]::after{content:' ▲'}th[aria-sort=descending]::after{content:' ▼'}\
.match{background:#dfd}.differs{background:#fed}.missing,.unreadable,.wrong-size{background:#fdd}\
.skipped{color:#777}pre{background:#f6f6f6;padding:6px;white-space:pre-wrap}\
img{image-rendering:pixelated;max-width:100%}code{background:#f6f6f6}";

/// Sorts the table by a header's column when it is clicked: by each cell's `data-sort` (a
/// number where it is one), again to reverse.
const SORT_SCRIPT: &str = "document.querySelectorAll('table.sortable th').forEach((th,col)=>{\
th.addEventListener('click',()=>{const table=th.closest('table');const body=table.tBodies[0];\
const down=th.getAttribute('aria-sort')==='ascending';\
table.querySelectorAll('th').forEach(h=>h.removeAttribute('aria-sort'));\
th.setAttribute('aria-sort',down?'descending':'ascending');\
const key=r=>{const c=r.cells[col];const v=c?(c.dataset.sort??c.textContent):'';\
const n=Number(v);return v!==''&&!isNaN(n)?n:v.toLowerCase()};\
const rows=[...body.rows].sort((a,b)=>{const x=key(a),y=key(b);\
const o=typeof x===typeof y?(x<y?-1:x>y?1:0):(typeof x==='number'?-1:1);return down?-o:o});\
rows.forEach(r=>body.appendChild(r))})});";

/// The start of a page titled `title`.
fn head(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width\">\
         <title>{}</title><style>{STYLE}</style></head><body>\n",
        escape(title)
    )
}

/// A status as a class name.
fn class_of(status: &str) -> String {
    status.replace(' ', "-")
}

/// The class table.
pub(super) fn index_page(class: &ClassReport) -> String {
    let mut page = head("Grades");
    let columns = class.columns();
    let graded = class.graded_count();
    let _ = writeln!(
        page,
        "<h1>Grades</h1>\n<p>Assignment <code>{}</code>, submissions in <code>{}</code>: {}. \
         Made by raytracer {}.</p>",
        escape(&class.assignment),
        escape(&class.submissions_folder),
        escape(&class.summary()),
        env!("CARGO_PKG_VERSION"),
    );
    let totals = class.deviation_totals();
    if !totals.is_empty() {
        let _ = writeln!(
            page,
            "<h2>What the class did differently</h2>\n<ul id=\"deviations\">"
        );
        let mut by_count: Vec<(&String, &usize)> = totals.iter().collect();
        by_count.sort_by(|a, b| b.1.cmp(a.1).then(a.0.cmp(b.0)));
        for (word, count) in by_count {
            let _ = writeln!(
                page,
                "<li><b>{}</b>: {count} of {graded} submissions</li>",
                escape(word)
            );
        }
        let _ = writeln!(page, "</ul>");
    }
    let _ = writeln!(
        page,
        "<h2>Submissions</h2>\n<p>Click a column's title to sort by it.</p>\n\
         <table class=\"sortable\" id=\"grades\"><thead><tr><th>submission</th><th>matching</th>"
    );
    for (index, kind, name) in &columns {
        let _ = write!(
            page,
            "<th title=\"{} ({})\">{}</th>",
            escape(&class.tasks[*index].line),
            kind.word(),
            escape(name)
        );
    }
    let _ = writeln!(page, "</tr></thead><tbody>");
    for graded in &class.graded {
        let name = escape(&graded.submission.name);
        if let Some(why) = &graded.submission.skipped {
            let _ = writeln!(
                page,
                "<tr class=\"skipped\"><td>{name}</td><td data-sort=\"-1\">skipped</td>\
                 <td colspan=\"{}\">{}</td></tr>",
                columns.len(),
                escape(why)
            );
            continue;
        }
        let _ = write!(
            page,
            "<tr><td><a href=\"{}\">{name}</a></td><td data-sort=\"{}\">{} of {}</td>",
            graded.page,
            graded.matching(),
            graded.matching(),
            graded.marks.len()
        );
        for (cell, (_, mark)) in graded.marks.iter().enumerate() {
            let state = status(mark);
            let _ = write!(
                page,
                "<td class=\"{}\" data-sort=\"{}\"><a href=\"{}#image-{cell}\">{}</a></td>",
                class_of(state),
                escape(state),
                graded.page,
                escape(&short(mark))
            );
        }
        let _ = writeln!(page, "</tr>");
    }
    let _ = writeln!(page, "</tbody></table>");
    let _ = writeln!(
        page,
        "<h2>Per image</h2>\n<table id=\"per-image\"><thead><tr><th>image</th>\
         <th>match</th><th>differs</th><th>missing</th><th>unreadable</th><th>wrong size</th></tr></thead><tbody>"
    );
    for (column, (_, _, name)) in columns.iter().enumerate() {
        let _ = write!(page, "<tr><td>{}</td>", escape(name));
        for wanted in ["match", "differs", "missing", "unreadable", "wrong size"] {
            let count = class
                .graded
                .iter()
                .filter(|g| {
                    g.marks
                        .get(column)
                        .is_some_and(|(_, m)| status(m) == wanted)
                })
                .count();
            let _ = write!(page, "<td>{count} of {graded}</td>");
        }
        let _ = writeln!(page, "</tr>");
    }
    let _ = writeln!(
        page,
        "</tbody></table>\n<p>The same as <a href=\"report.json\">JSON</a> and \
         <a href=\"report.csv\">CSV</a>.</p>\n<script>{SORT_SCRIPT}</script>\n</body></html>"
    );
    page
}

/// The command that gives the same answer for one image.
fn command_of(class: &ClassReport, index: usize, mark: &Mark) -> Option<String> {
    let task = &class.tasks[index];
    let path = mark.path.as_ref()?;
    let quote = |p: &std::path::Path| shell_quote_path(p);
    let their = match (mark.kind, &task.depth) {
        (ImageKind::Depth, Some((range, _))) => {
            format!(
                "-compare_depth {} {} {}",
                range.min_t,
                range.max_t,
                quote(path)
            )
        }
        _ => format!("-compare_output {}", quote(path)),
    };
    Some(format!(
        "raytracer -input {} -size {} {} {their} -diff diff.png",
        quote(&task.scene),
        task.size_px.0,
        task.size_px.1
    ))
}

/// One submission's page.
pub(super) fn submission_page(class: &ClassReport, graded: &Graded) -> String {
    let name = escape(&graded.submission.name);
    let mut page = head(&format!("{} — grades", graded.submission.name));
    let _ = writeln!(
        page,
        "<p><a href=\"../index.html\">← the class</a></p>\n<h1>{name}</h1>\n<p>{} of {} images match.</p>",
        graded.matching(),
        graded.marks.len()
    );
    if let Some(why) = &graded.submission.skipped {
        let _ = writeln!(page, "<p>Not graded: {}.</p>", escape(why));
    }
    for (cell, (index, mark)) in graded.marks.iter().enumerate() {
        let task = &class.tasks[*index];
        let state = status(mark);
        let _ = writeln!(
            page,
            "<section id=\"image-{cell}\"><h2>{} — {} ({})</h2>\n<p>Line {} of the assignment: <code>{}</code></p>\n\
             <p class=\"{}\"><b>{}</b></p>",
            escape(&task.name()),
            escape(&mark.wanted.display().to_string()),
            mark.kind.word(),
            task.line_number,
            escape(&task.line),
            class_of(state),
            escape(&short(mark)),
        );
        if let Some(renamed) = &mark.renamed {
            let _ = writeln!(
                page,
                "<p>Found as <code>{}</code> (the name differs in letter case or extension).</p>",
                escape(renamed)
            );
        }
        match &mark.outcome {
            Outcome::Compared(answer) => {
                let statements: Vec<_> = answer.statements_on(mark.kind).collect();
                if !statements.is_empty() {
                    let _ = writeln!(page, "<ul>");
                    for statement in statements {
                        let _ = writeln!(page, "<li>{}</li>", escape(&statement.said));
                    }
                    let _ = writeln!(page, "</ul>");
                }
                if !answer.alternatives.is_empty() {
                    let _ = writeln!(
                        page,
                        "<p>One of these (they draw nearly the same pixels):</p><ul>"
                    );
                    for set in &answer.alternatives {
                        let said: Vec<String> = set.iter().map(|s| escape(&s.said)).collect();
                        let _ = writeln!(page, "<li>{}</li>", said.join("<br>and "));
                    }
                    let _ = writeln!(page, "</ul>");
                }
                if !answer.partial.is_empty() {
                    let _ = writeln!(page, "<p>In part:</p><ul>");
                    for statement in &answer.partial {
                        let _ = writeln!(page, "<li>{}</li>", escape(&statement.said));
                    }
                    let _ = writeln!(page, "</ul>");
                }
                if let Some(picture) = &answer.picture {
                    let _ = writeln!(
                        page,
                        "<p>Theirs, the exact image, the difference and the pixels no statement \
                         explains:</p>\n<img src=\"../{picture}\" alt=\"difference picture\">"
                    );
                } else {
                    let _ = writeln!(
                        page,
                        "<img src=\"../{}\" alt=\"the exact image\">",
                        exact_image(*index, mark.kind)
                    );
                }
                let _ = writeln!(
                    page,
                    "<p>The whole answer:</p><pre>{}</pre>",
                    escape(&answer.lines)
                );
            }
            _ => {
                let _ = writeln!(
                    page,
                    "<p>The exact image:</p><img src=\"../{}\" alt=\"the exact image\">",
                    exact_image(*index, mark.kind)
                );
            }
        }
        if let Some(command) = command_of(class, *index, mark) {
            let _ = writeln!(
                page,
                "<p>The same answer from the command line:</p><pre>{}</pre>",
                escape(&command)
            );
        }
        let _ = writeln!(page, "</section>");
    }
    let _ = writeln!(page, "</body></html>");
    page
}
