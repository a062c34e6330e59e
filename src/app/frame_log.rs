//! The frame log: with `RAYTRACER_FRAME_LOG=FILE` in the environment the viewer appends a line
//! per frame it draws, so a script driving the real window can measure what the user sees
//! (`cargo xtask report window-frame-times`):
//!
//! * `renderer NAME`: first, the renderer painting the window (`glow` or `wgpu`);
//! * `ui MS`: the UI thread's time for the previous frame (egui's layout, tessellation and paint,
//!   as eframe measures it);
//! * `frame RENDER_MS LATENCY_MS WIDTH HEIGHT`: a new frame from the worker — its render time
//!   (what the status bar shows), and the time from the UI frame that changed the view to the
//!   one that takes the picture of it in;
//! * `missing-glyphs N NAME`: the scene's name as the status bar shows it, and how many of its
//!   characters no font has (each drawn as a box), whenever either changes — text in other
//!   scripts comes from the system's fonts, looked up as it appears.

use std::fs::File;
use std::io::{BufWriter, Write};
use web_time::Instant;

/// The environment variable naming the log file.
pub const FRAME_LOG_VARIABLE: &str = "RAYTRACER_FRAME_LOG";

/// An open frame log.
pub(crate) struct FrameLog {
    out: BufWriter<File>,
    /// The last `missing-glyphs` line written.
    glyphs_line: String,
}

impl FrameLog {
    /// The log the environment asks for, if any (a file that cannot be created: none).
    pub(crate) fn from_environment() -> Option<Self> {
        let path = std::env::var_os(FRAME_LOG_VARIABLE)?;
        let file = File::create(path).ok()?;
        Some(Self {
            out: BufWriter::new(file),
            glyphs_line: String::new(),
        })
    }

    /// The renderer that paints the window (`glow` or `wgpu`), once at the start.
    pub(crate) fn renderer(&mut self, name: &str) {
        let _ = writeln!(self.out, "renderer {name}");
        let _ = self.out.flush();
    }

    /// The UI thread's seconds for the previous frame.
    pub(crate) fn ui(&mut self, seconds: Option<f32>) {
        if let Some(seconds) = seconds {
            let _ = writeln!(self.out, "ui {:.3}", f64::from(seconds) * 1e3);
            let _ = self.out.flush();
        }
    }

    /// A new frame from the worker, of a view that changed at `changed_at`.
    pub(crate) fn frame(&mut self, render_ms: f64, changed_at: Option<Instant>, size_px: [u32; 2]) {
        let latency_ms = changed_at.map_or(f64::NAN, |at| at.elapsed().as_secs_f64() * 1e3);
        let _ = writeln!(
            self.out,
            "frame {render_ms:.3} {latency_ms:.3} {} {}",
            size_px[0], size_px[1]
        );
        // Written as it goes: the script stops the viewer with a signal.
        let _ = self.out.flush();
    }

    /// How many characters of `name` (the scene's, in the status bar) no font has, asked of the
    /// fonts that draw it (the system's fonts found as the characters appear included).
    pub(crate) fn missing_glyphs(&mut self, ctx: &egui::Context, name: &str) {
        let font = egui::FontId::proportional(14.0);
        let missing = ctx.fonts_mut(|fonts| {
            name.chars()
                .filter(|&c| !c.is_whitespace() && !fonts.has_glyph(&font, c))
                .count()
        });
        let line = format!("missing-glyphs {missing} {name}");
        if line != self.glyphs_line {
            let _ = writeln!(self.out, "{line}");
            let _ = self.out.flush();
            self.glyphs_line = line;
        }
    }
}
