//! Writing the report's files into the folder it is made in: the exact images (`exact/`), the
//! table (`index.html`), a page per submission (`pages/`), and `report.json` and `report.csv`.

use std::path::Path;

use super::html;
use super::mark::{Exact, ImageKind, make_subfolder, png_bytes};
use super::report::{ClassReport, exact_image};
use super::tables;

/// Writes the exact images to `folder`'s `exact/`.
pub(super) fn write_exact_images(folder: &Path, exacts: &[Exact]) -> Result<(), String> {
    let write = |relative: String, bytes: Vec<u8>| {
        std::fs::write(folder.join(&relative), bytes).map_err(|e| format!("{relative}: {e}"))
    };
    make_subfolder(&folder.join("exact")).map_err(|e| e.to_string())?;
    for (index, exact) in exacts.iter().enumerate() {
        if exact.task.colour.is_some() {
            write(
                exact_image(index, ImageKind::Colour),
                png_bytes(&exact.frame.colour_image())?,
            )?;
        }
        if let Some((range, _)) = exact.task.depth {
            write(
                exact_image(index, ImageKind::Depth),
                png_bytes(&exact.frame.depth_image(range))?,
            )?;
        }
    }
    Ok(())
}

/// Writes the table, the pages and the JSON and CSV forms to `folder`.
pub(super) fn write_report(folder: &Path, class: &ClassReport) -> Result<(), String> {
    let write = |relative: &str, text: String| {
        std::fs::write(folder.join(relative), text).map_err(|e| format!("{relative}: {e}"))
    };
    make_subfolder(&folder.join("pages")).map_err(|e| e.to_string())?;
    for graded in &class.graded {
        write(&graded.page, html::submission_page(class, graded))?;
    }
    write("index.html", html::index_page(class))?;
    // The JSON and CSV forms are written as they are made, never held whole.
    let stream =
        |relative: &str,
         write: &dyn Fn(&mut std::io::BufWriter<std::fs::File>) -> std::io::Result<()>| {
            let failed = |e: std::io::Error| format!("{relative}: {e}");
            let file = std::fs::File::create(folder.join(relative)).map_err(failed)?;
            let mut out = std::io::BufWriter::new(file);
            write(&mut out).map_err(failed)?;
            out.into_inner()
                .map_err(|e| failed(e.into_error()))?
                .sync_all()
                .map_err(failed)
        };
    stream("report.json", &|out| tables::write_json(class, out))?;
    stream("report.csv", &|out| tables::write_csv(class, out))
}
