//! The viewer's settings that survive a restart (eframe storage): the last scene, the panel,
//! export, quality and depth-display options, and the views kept per scene file.

use std::path::{Path, PathBuf};

use crate::export::ExtraDepth;
use crate::render::depth_map::DepthColourMap;

/// Image formats offered by the export panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum ExportFormat {
    /// `.png`
    Png,
    /// `.tga`
    Tga,
}

/// Export options, remembered between runs.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct ExportSettings {
    /// Where to write: `<stem>_colour.<ext>`, `<stem>_depth.<ext>`, `<stem>_both.<ext>`.
    pub path: String,
    /// Image format.
    pub format: ExportFormat,
    /// Also write colour and depth side by side in one picture.
    pub side_by_side: bool,
    /// Under the side-by-side picture, a legend: the colour bar and the depth range.
    pub legend: bool,
    /// Export at the displayed size (`true`) or at `size_px`.
    pub displayed_size: bool,
    /// Export size when not the displayed size.
    pub size_px: [u32; 2],
    /// Lossless or 16-bit depth written besides the 8-bit images.
    pub extra_depth: ExtraDepth,
    /// Where "save view as scene" writes when no dialog is used.
    pub scene_path: String,
}

impl Default for ExportSettings {
    fn default() -> Self {
        Self {
            path: "raytracer.png".into(),
            format: ExportFormat::Png,
            side_by_side: true,
            legend: true,
            displayed_size: true,
            size_px: [1024, 1024],
            extra_depth: ExtraDepth::None,
            scene_path: "view.txt".into(),
        }
    }
}

/// Everything persisted in eframe's storage (window size is persisted by eframe itself).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Settings {
    /// The last scene file opened successfully.
    pub(crate) last_scene: Option<PathBuf>,
    /// Whether the controls panel is open.
    pub(crate) show_controls: bool,
    /// Export options.
    pub export: ExportSettings,
    /// Rendering quality (samples per pixel).
    pub quality: crate::render::Quality,
    /// How the depth image is drawn.
    pub depth: DepthDisplay,
    /// Per scene file: the view it was last seen in, and the views the user named.
    pub views: super::saved_views::SceneViews,
}

/// How the depth image is drawn on screen (and exported).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct DepthDisplay {
    /// One of [`DepthColourMap::ALL`]; grey is the course's.
    pub colour_map: DepthColourMap,
    /// Show no-hit pixels in the map's mark ([`no_hit_mark`]) on screen instead
    /// of black, so they stand apart from far ones. Files keep black.
    pub mark_no_hit: bool,
    /// "Auto range" ignores this percentage of the visible t at each end (0: min to max).
    pub auto_cut_percent: f64,
    /// The histogram's bars on a logarithmic scale of the counts.
    pub log_counts: bool,
    /// Keep fitting the depth range to the visible t while the view changes.
    pub follow: bool,
}

impl Default for DepthDisplay {
    fn default() -> Self {
        Self {
            colour_map: DepthColourMap::Grey,
            mark_no_hit: true,
            auto_cut_percent: 1.0,
            log_counts: false,
            follow: false,
        }
    }
}

/// The on-screen colour of no-hit pixels on the grey map when the viewer marks them (a dark blue
/// that the grey ramp never produces).
const NO_HIT_MARK: [u8; 3] = [24, 36, 96];

/// ... and on the colour maps (a light grey, which neither produces).
const NO_HIT_MARK_ON_COLOURS: [u8; 3] = [200, 200, 200];

/// The on-screen colour of no-hit pixels when the viewer marks them: a colour far from every
/// colour of `map`. Grey: a dark blue (the grey ramp has no colour). Turbo and viridis: a light
/// grey (their colours are saturated; viridis's dark blues lie within 50 of the dark blue in
/// 8-bit RGB, and turbo's far end is a blue too).
pub(crate) fn no_hit_mark(map: DepthColourMap) -> [u8; 3] {
    match map {
        DepthColourMap::Grey => NO_HIT_MARK,
        DepthColourMap::Turbo | DepthColourMap::Viridis => NO_HIT_MARK_ON_COLOURS,
    }
}

impl DepthDisplay {
    /// The on-screen colour of no-hit pixels.
    pub(crate) fn no_hit_rgb(&self) -> [u8; 3] {
        if self.mark_no_hit {
            no_hit_mark(self.colour_map)
        } else {
            DepthColourMap::FILE_NO_HIT
        }
    }
}

impl Settings {
    /// The settings eframe's `storage` kept (the defaults when there are none); a size asked for
    /// on the command line (`-size W H`) becomes the export's size.
    pub(crate) fn from_storage(
        storage: Option<&dyn eframe::Storage>,
        size_px: Option<(u32, u32)>,
    ) -> Self {
        let mut settings: Self = storage
            .and_then(|storage| eframe::get_value(storage, eframe::APP_KEY))
            .unwrap_or_default();
        if let Some((width, height)) = size_px {
            settings.export.displayed_size = false;
            settings.export.size_px = [width, height];
        }
        settings
    }
}

impl Settings {
    /// A scene opened from `path` after the one from `previous`, which was in `view` (remembered
    /// for when it is opened again): exports follow its name (unless the user chose one), and a
    /// file (not `in_memory`) is the one to open at the next start.
    pub(crate) fn follow_open(
        &mut self,
        previous: Option<&Path>,
        view: &crate::render::View,
        path: &Path,
        in_memory: bool,
    ) {
        self.views.remember(previous, view);
        let export = &mut self.export;
        if let Some(followed) = crate::export::export_path_following(
            &export.path,
            &crate::export::name_in_folder(previous),
            &crate::export::name_in_folder(Some(path)),
        ) {
            export.path = followed;
        }
        if !in_memory {
            self.last_scene = Some(path.to_path_buf());
        }
    }
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            last_scene: None,
            show_controls: true,
            export: ExportSettings::default(),
            quality: crate::render::Quality::default(),
            depth: DepthDisplay::default(),
            views: super::saved_views::SceneViews::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_maps_no_hit_mark_lies_far_from_its_colours() {
        // Every map's no-hit mark lies at least as far from every colour of its map (in 8-bit
        // RGB) as the grey map's dark blue lies from the nearest grey, 54.6. The dark blue on
        // viridis: 49.6.
        for map in DepthColourMap::ALL {
            let mark = no_hit_mark(map).map(f64::from);
            let nearest = (0..=1000)
                .map(|step| {
                    let colour = map.rgb_of_grey(f64::from(step) / 1000.0).map(f64::from);
                    let d: [f64; 3] = std::array::from_fn(|c| colour[c] - mark[c]);
                    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
                })
                .fold(f64::INFINITY, f64::min);
            assert!(nearest >= 54.0, "{map}: the mark is {nearest} from the map");
        }
    }
}
