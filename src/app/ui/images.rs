//! The central area: the colour and depth images — side by side, or one above the other when
//! that shows them larger (narrow windows) — and under them the pixel probe and the depth
//! histogram, in a compact form in short windows. Each image has a frame, the pinned pixel's
//! ring and a crosshair at the pixel under the pointer (on both images); the magnifier enlarges
//! both together. Pointer input comes back as [`ImageGestures`]; nothing here changes the view
//! itself except the histogram's handles.

use egui::{Color32, Pos2, Rect, Sense, Stroke, TextureHandle, Ui, Vec2};
use glam::DVec2;

use super::gestures::{ImageGestures, read_gestures};
use super::histogram::{HistogramStyle, histogram_ui};
use super::magnifier::{Magnifier, Region};
use super::probe_panel::probe_ui;
use crate::app::depth_stats::DepthHistogram;
use crate::compare::picture::heat_colour;
use crate::export::numbers::range_ends;
use crate::render::MAX_SIDE_PX;
use crate::render::depth_map::{DepthColourMap, DepthRange};

/// Space between the two images, in points.
const IMAGE_GAP_POINTS: f32 = 8.0;

/// Width of the frame drawn around each image, in points.
const FRAME_POINTS: f32 = 1.0;

/// Height reserved for the caption above each image, in points.
const CAPTION_POINTS: f32 = 20.0;

/// Height under the images for the probe and the histogram, in points.
const FOOTER_POINTS: f32 = 112.0;

/// The same in short windows.
const COMPACT_FOOTER_POINTS: f32 = 64.0;

/// Below this height of the area the footer is compact.
const COMPACT_BELOW_POINTS: f32 = 520.0;

/// Accessible labels of the two images (tests find them by these).
pub(crate) const IMAGE_LABELS: [&str; 2] = ["colour image", "depth image"];

/// The textures of the frame on screen and what goes with them.
pub(crate) struct ShownImages<'a> {
    /// Colour texture.
    pub(crate) colour: &'a TextureHandle,
    /// Depth texture.
    pub(crate) depth: &'a TextureHandle,
    /// Frame size in physical pixels.
    pub(crate) size_px: [u32; 2],
    /// Depth range the depth texture was mapped with.
    pub(crate) depth_range: DepthRange,
    /// Visible t of the frame.
    pub(crate) histogram: Option<&'a DepthHistogram>,
    /// Pictures shown in place of the two (the Compare section's): one, or one for each image
    /// of a pair.
    pub(crate) compared: Vec<Compared<'a>>,
}

/// A picture shown in place of one of the rendered images: their image or the difference.
pub(crate) struct Compared<'a> {
    /// Which image it replaces (0 colour, 1 depth).
    pub(crate) index: usize,
    /// Its texture.
    pub(crate) texture: &'a TextureHandle,
    /// Its size in pixels.
    pub(crate) size_px: [u32; 2],
    /// Its caption.
    pub(crate) caption: String,
    /// It is the difference's heat map: its scale is drawn beside the caption.
    pub(crate) heat_scale: bool,
}

/// What the area shows and edits besides the images.
pub(crate) struct Footer<'a> {
    /// Lines of the pixel probe (hovered and pinned pixel).
    pub(crate) probe_lines: &'a [String],
    /// The pinned pixel, if it is in view.
    pub(crate) pinned: Option<DVec2>,
    /// A pixel is pinned (an "Unpin" button is shown), in view or not.
    pub(crate) has_pin: bool,
    /// The pixel under the pointer.
    pub(crate) hover: Option<DVec2>,
    /// The depth range the histogram's handles edit (the current view's).
    pub(crate) depth_range: &'a mut DepthRange,
    /// How the histogram is drawn.
    pub(crate) histogram_style: HistogramStyle,
    /// Colour map for the histogram's legend.
    pub(crate) colour_map: DepthColourMap,
    /// Colour of no-hit pixels on screen.
    pub(crate) no_hit_rgb: [u8; 3],
    /// The magnifier.
    pub(crate) magnifier: Magnifier,
}

/// How the two images share the area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Arrangement {
    /// Colour left, depth right.
    SideBySide,
    /// Colour above, depth below.
    Stacked,
}

/// Where things go in the area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AreaLayout {
    pub(crate) arrangement: Arrangement,
    /// The space of one image, points.
    pub(crate) image_points: Vec2,
    /// The footer's height, points.
    pub(crate) footer_points: f32,
}

/// The arrangement that shows the images larger (by their shorter side) in `available` points.
pub(crate) fn area_layout(available: Vec2) -> AreaLayout {
    let footer_points = if available.y < COMPACT_BELOW_POINTS {
        COMPACT_FOOTER_POINTS
    } else {
        FOOTER_POINTS
    };
    let side_by_side = Vec2::new(
        (available.x - IMAGE_GAP_POINTS) * 0.5,
        available.y - CAPTION_POINTS - footer_points,
    );
    let stacked = Vec2::new(
        available.x,
        (available.y - 2.0 * CAPTION_POINTS - IMAGE_GAP_POINTS - footer_points) * 0.5,
    );
    let shorter = |v: Vec2| v.x.min(v.y);
    let (arrangement, image_points) = if shorter(stacked) > shorter(side_by_side) {
        (Arrangement::Stacked, stacked)
    } else {
        (Arrangement::SideBySide, side_by_side)
    };
    AreaLayout {
        arrangement,
        image_points: image_points.max(Vec2::splat(1.0)),
        footer_points,
    }
}

/// The image size (physical pixels) that fills one image's space of the area `available_points`
/// at `pixels_per_point`.
pub(crate) fn image_size_px(
    available_points: Vec2,
    pixels_per_point: f32,
    max_texture_side: usize,
) -> (u32, u32) {
    let space = area_layout(available_points).image_points;
    let max_side = (max_texture_side as f32).min(MAX_SIDE_PX as f32);
    let to_px = |points: f32| (points * pixels_per_point).floor().clamp(1.0, max_side) as u32;
    (to_px(space.x), to_px(space.y))
}

/// Where a frame of `size_px` is drawn in `area`: scaled to fit, square pixels, snapped to the
/// physical pixel grid so a 1:1 frame is shown without resampling.
fn image_rect(area: Rect, size_px: [u32; 2], pixels_per_point: f32) -> Rect {
    let frame_points = Vec2::new(size_px[0] as f32, size_px[1] as f32) / pixels_per_point;
    let scale = (area.width() / frame_points.x).min(area.height() / frame_points.y);
    let min = ((area.min.to_vec2() * pixels_per_point).round() / pixels_per_point).to_pos2();
    Rect::from_min_size(min, frame_points * scale)
}

/// The images, the probe and the histogram. Returns the pointer gestures and the image size the
/// area asks for.
pub(crate) fn images_ui(
    ui: &mut Ui,
    shown: Option<&ShownImages<'_>>,
    footer: Footer<'_>,
) -> ImageGestures {
    let pixels_per_point = ui.ctx().pixels_per_point();
    let available = ui.available_size();
    let max_texture_side = ui.ctx().input(|i| i.max_texture_side);
    let layout = area_layout(available);
    let mut gestures = ImageGestures {
        wanted_px: image_size_px(available, pixels_per_point, max_texture_side),
        ..ImageGestures::default()
    };
    let captions = captions(shown);
    let Footer {
        probe_lines,
        pinned,
        has_pin,
        hover,
        depth_range,
        histogram_style,
        colour_map,
        no_hit_rgb,
        magnifier,
    } = footer;
    let marks = Marks {
        pinned,
        hover,
        magnifier,
    };
    let heat_scale_on: Vec<usize> = shown
        .iter()
        .flat_map(|s| &s.compared)
        .filter(|compared| compared.heat_scale)
        .map(|compared| compared.index)
        .collect();
    let mut image = |ui: &mut Ui, index: usize| {
        // One line: a long caption is elided (whole on hover), so it never pushes the footer out.
        ui.horizontal(|ui| {
            ui.set_width(layout.image_points.x);
            if heat_scale_on.contains(&index) {
                heat_scale_ui(ui);
            }
            ui.add(egui::Label::new(&captions[index]).truncate());
        });
        image_ui(ui, index, layout.image_points, shown, marks, &mut gestures);
    };
    let half_width = |ui: &Ui| ((ui.available_width() - IMAGE_GAP_POINTS) * 0.5).max(1.0);
    match layout.arrangement {
        Arrangement::SideBySide => {
            ui.horizontal_top(|ui| {
                ui.spacing_mut().item_spacing.x = IMAGE_GAP_POINTS;
                for index in 0..2 {
                    ui.vertical(|ui| {
                        ui.set_width(layout.image_points.x);
                        image(ui, index);
                    });
                }
            });
        }
        Arrangement::Stacked => {
            ui.spacing_mut().item_spacing.y = IMAGE_GAP_POINTS;
            image(ui, 0);
            image(ui, 1);
        }
    }
    let footer_size = Vec2::new(ui.available_width(), layout.footer_points);
    ui.allocate_ui(footer_size, |ui| {
        ui.horizontal_top(|ui| {
            ui.spacing_mut().item_spacing.x = IMAGE_GAP_POINTS;
            let width = half_width(ui);
            ui.vertical(|ui| {
                ui.set_width(width);
                let asked = probe_ui(ui, probe_lines, has_pin, layout.footer_points - 4.0);
                gestures.unpin = asked.unpin;
                gestures.trace = asked.trace;
            });
            ui.vertical(|ui| {
                ui.set_width(width);
                let histogram = shown.and_then(|s| s.histogram);
                let height = layout.footer_points;
                gestures.depth_range_dragged = histogram_ui(
                    ui,
                    histogram,
                    depth_range,
                    histogram_style.with_height(height),
                    colour_map,
                    no_hit_rgb,
                );
            });
        });
    });
    gestures
}

/// Label of the heat map's scale (tests find it by this).
pub(crate) const HEAT_SCALE_LABEL: &str = "heat map scale";

/// Width of the heat map's colour bar, points.
const HEAT_BAR_POINTS: f32 = 96.0;

/// The heat map's scale, at the start of its caption: "1", a bar of the colours a difference of
/// 1 to 255 levels takes, "255", so the heat map reads without a key elsewhere.
fn heat_scale_ui(ui: &mut Ui) {
    let response = ui
        .horizontal(|ui| {
            ui.spacing_mut().item_spacing.x = 3.0;
            ui.label("1");
            let height = ui.text_style_height(&egui::TextStyle::Body) * 0.8;
            let (bar, _) =
                ui.allocate_exact_size(Vec2::new(HEAT_BAR_POINTS, height), Sense::hover());
            let painter = ui.painter_at(bar);
            let steps = HEAT_BAR_POINTS as usize;
            for step in 0..steps {
                let levels = 1 + (step * 254 / (steps - 1)) as u8;
                let [r, g, b] = heat_colour(levels);
                let x = bar.left() + step as f32;
                painter.rect_filled(
                    Rect::from_min_max(Pos2::new(x, bar.top()), Pos2::new(x + 1.0, bar.bottom())),
                    0.0,
                    Color32::from_rgb(r, g, b),
                );
            }
            ui.label("255 levels ·");
        })
        .response;
    response.widget_info(|| {
        egui::WidgetInfo::labeled(egui::Role::Image, true, HEAT_SCALE_LABEL.to_owned())
    });
}

/// The captions above the two images.
fn captions(shown: Option<&ShownImages<'_>>) -> [String; 2] {
    let mut captions = match shown {
        Some(images) => {
            let [near, far] = range_ends(images.depth_range.min_t, images.depth_range.max_t);
            [
                "colour".to_owned(),
                format!("depth  (t {near} near … {far} far)"),
            ]
        }
        None => ["colour".to_owned(), "depth".to_owned()],
    };
    for compared in shown.iter().flat_map(|s| &s.compared) {
        captions[compared.index].clone_from(&compared.caption);
    }
    captions
}

/// What is drawn over both images.
#[derive(Clone, Copy)]
struct Marks {
    pinned: Option<DVec2>,
    hover: Option<DVec2>,
    magnifier: Magnifier,
}

/// One image in a space of `space` points: the texture (the magnifier's region of it), its frame,
/// the pixel grid when magnified, the pinned pixel's ring and the crosshair.
fn image_ui(
    ui: &mut Ui,
    index: usize,
    space: Vec2,
    shown: Option<&ShownImages<'_>>,
    marks: Marks,
    gestures: &mut ImageGestures,
) {
    let (area, response) = ui.allocate_exact_size(space, Sense::click_and_drag());
    let label = IMAGE_LABELS[index];
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, label.to_owned()));
    let Some(images) = shown else {
        ui.painter().rect_filled(area, 0.0, Color32::from_gray(30));
        return;
    };
    let compared = images.compared.iter().find(|c| c.index == index);
    let (texture, size_px) = match compared {
        Some(compared) => (compared.texture, compared.size_px),
        None if index == 0 => (images.colour, images.size_px),
        None => (images.depth, images.size_px),
    };
    let rect = image_rect(area, size_px, ui.ctx().pixels_per_point());
    let region = marks.magnifier.region(size_px);
    let painter = ui.painter_at(area);
    painter.image(texture.id(), rect, region.uv(size_px), Color32::WHITE);
    region.paint_grid(&painter, rect);
    // A frame just outside the image (in the gap around the area, never over a pixel), so a
    // background as dark as the panel still shows where the image ends.
    ui.painter()
        .with_clip_rect(area.expand(FRAME_POINTS + 1.0))
        .rect_stroke(
            rect,
            0.0,
            Stroke::new(FRAME_POINTS, ui.visuals().weak_text_color()),
            egui::StrokeKind::Outside,
        );
    if let Some(pin) = marks.pinned {
        let at = region.pos_of_image_px(pin, rect);
        painter.circle_stroke(at, 5.0, Stroke::new(2.0, Color32::BLACK));
        painter.circle_stroke(at, 4.0, Stroke::new(1.5, Color32::WHITE));
    }
    if let Some(hover) = marks.hover {
        paint_crosshair(&painter, region, rect, hover);
    }
    read_gestures(ui, &response, rect, region, gestures);
}

/// A crosshair at the centre of the pixel `hover` (image pixels, y up), in black and white so it
/// shows on any colour.
fn paint_crosshair(painter: &egui::Painter, region: Region, rect: Rect, hover: DVec2) {
    let centre = region.pos_of_image_px(hover.floor() + DVec2::splat(0.5), rect);
    if !rect.contains(centre) {
        return;
    }
    for (width, colour) in [(3.0, Color32::BLACK), (1.0, Color32::WHITE)] {
        let stroke = Stroke::new(width, colour);
        let arm = 9.0;
        painter.line_segment([centre - Vec2::X * arm, centre - Vec2::X * 3.0], stroke);
        painter.line_segment([centre + Vec2::X * 3.0, centre + Vec2::X * arm], stroke);
        painter.line_segment([centre - Vec2::Y * arm, centre - Vec2::Y * 3.0], stroke);
        painter.line_segment([centre + Vec2::Y * 3.0, centre + Vec2::Y * arm], stroke);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn render_size_follows_physical_pixels() {
        // 808 points wide: two images of (808 − 8) / 2 = 400 points side by side; the height is
        // what the caption and the footer leave.
        let height = 600.0 + CAPTION_POINTS + FOOTER_POINTS;
        let area = Vec2::new(808.0, height);
        assert_eq!(area_layout(area).arrangement, Arrangement::SideBySide);
        assert_eq!(image_size_px(area, 1.0, 8192), (400, 600));
        assert_eq!(image_size_px(area, 2.0, 8192), (800, 1200));
        assert_eq!(image_size_px(area, 1.5, 8192), (600, 900));
        // Never larger than a texture may be, never empty.
        assert_eq!(image_size_px(area, 2.0, 1000), (800, 1000));
        assert_eq!(image_size_px(Vec2::ZERO, 1.0, 8192), (1, 1));
    }

    #[test]
    fn narrow_tall_areas_stack_the_images_and_short_ones_shrink_the_footer() {
        let tall = area_layout(Vec2::new(400.0, 900.0));
        assert_eq!(tall.arrangement, Arrangement::Stacked);
        assert!(tall.image_points.x.min(tall.image_points.y) > 300.0);
        let short = area_layout(Vec2::new(400.0, 250.0));
        assert_eq!(short.arrangement, Arrangement::SideBySide);
        assert_eq!(short.footer_points, COMPACT_FOOTER_POINTS);
        assert!(short.image_points.x.min(short.image_points.y) >= 130.0);
    }
}
