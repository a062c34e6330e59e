//! The central area: the colour and depth images side by side, and under them the pixel probe
//! (left) and the depth histogram with its legend (right). Pointer input on either image comes
//! back as [`ImageGestures`] in image pixels (y up), which the viewer turns into navigation (see
//! [`crate::explore::navigate`]); nothing here changes the view itself except the histogram's handles.

use egui::{Color32, PointerButton, Pos2, Rect, RichText, Sense, Stroke, TextureHandle, Ui, Vec2};
use glam::DVec2;

use super::histogram::{HISTOGRAM_POINTS, histogram_ui};
use super::probe_text::short_number;
use crate::explore::depth_stats::DepthHistogram;
use crate::render::MAX_SIDE_PX;
use crate::render::depth_map::{DepthColourMap, DepthRange};

/// Space between the two images, in points.
const IMAGE_GAP_POINTS: f32 = 8.0;

/// Height reserved for the caption above each image, in points.
const CAPTION_POINTS: f32 = 20.0;

/// Height reserved under the images for the probe and the histogram, in points.
pub(crate) const FOOTER_POINTS: f32 = HISTOGRAM_POINTS + 24.0;

/// Font size of the probe's lines, in points.
const PROBE_FONT_POINTS: f32 = 11.0;

/// Scrolling this many points zooms by a factor of two.
const SCROLL_POINTS_PER_DOUBLING: f64 = 240.0;

/// Orbit angle per point of drag, radians (a drag across 300 points turns about 90°).
pub const ORBIT_RAD_PER_POINT: f64 = std::f64::consts::FRAC_PI_2 / 300.0;

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
}

/// What the footer under the images shows and edits.
pub(crate) struct Footer<'a> {
    /// Lines of the pixel probe (hovered and pinned pixel).
    pub(crate) probe_lines: &'a [String],
    /// A pixel is pinned (an "unpin" button is shown).
    pub(crate) pinned: Option<DVec2>,
    /// The depth range the histogram's handles edit (the current view's).
    pub(crate) depth_range: &'a mut DepthRange,
    /// Colour map for the histogram's legend.
    pub(crate) colour_map: DepthColourMap,
    /// Colour of no-hit pixels on screen.
    pub(crate) no_hit_rgb: [u8; 3],
}

/// Pointer input on the images, in image pixels with y up (see [`crate::explore::navigate`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ImageGestures {
    /// Image size in physical pixels the area asks for.
    pub(crate) wanted_px: (u32, u32),
    /// Primary (or middle) drag: the picture should follow by this many pixels.
    pub(crate) pan_px: DVec2,
    /// Secondary drag, or a primary drag with Shift: orbit by these many points (x right, y up).
    pub(crate) orbit_points: DVec2,
    /// Wheel or pinch zoom: size factor (< 1 zooms in) and the anchor pixel.
    pub(crate) zoom: Option<(f64, DVec2)>,
    /// The pointer's position on the image, if it is over one.
    pub(crate) hover_px: Option<DVec2>,
    /// A click (no drag) on an image pins this position.
    pub(crate) clicked_px: Option<DVec2>,
    /// "Unpin" was clicked.
    pub(crate) unpin: bool,
    /// A histogram handle moved the depth range.
    pub(crate) depth_range_dragged: bool,
}

/// The image size (physical pixels) that fills half of the area `available_points` at
/// `pixels_per_point`: the two images side by side, each below its caption and above the footer.
pub(crate) fn image_size_px(
    available_points: Vec2,
    pixels_per_point: f32,
    max_texture_side: usize,
) -> (u32, u32) {
    let half = half_points(available_points);
    let max_side = (max_texture_side as f32).min(MAX_SIDE_PX as f32);
    let to_px = |points: f32| (points * pixels_per_point).floor().clamp(1.0, max_side) as u32;
    (to_px(half.x), to_px(half.y))
}

fn half_points(available: Vec2) -> Vec2 {
    Vec2::new(
        ((available.x - IMAGE_GAP_POINTS) * 0.5).max(1.0),
        (available.y - CAPTION_POINTS - FOOTER_POINTS).max(1.0),
    )
}

/// Position of `pos` on an image drawn in `rect` of `size_px` pixels: image pixels, y up.
pub(crate) fn image_px_of(pos: Pos2, rect: Rect, size_px: [u32; 2]) -> DVec2 {
    DVec2::new(
        f64::from((pos.x - rect.min.x) / rect.width()) * f64::from(size_px[0]),
        f64::from((rect.max.y - pos.y) / rect.height()) * f64::from(size_px[1]),
    )
}

/// Where image position `px` (pixels, y up) is drawn in `rect`.
fn pos_of_image_px(px: DVec2, rect: Rect, size_px: [u32; 2]) -> Pos2 {
    Pos2::new(
        rect.min.x + (px.x / f64::from(size_px[0])) as f32 * rect.width(),
        rect.max.y - (px.y / f64::from(size_px[1])) as f32 * rect.height(),
    )
}

/// The colour and depth images side by side, each scaled to fit its half while keeping square
/// pixels (at 1:1 physical pixels when the frame matches the area), with the probe and the
/// histogram under them. Returns the pointer gestures and the size the area asks for.
pub(crate) fn images_ui(
    ui: &mut Ui,
    shown: Option<&ShownImages<'_>>,
    Footer {
        probe_lines,
        pinned,
        depth_range,
        colour_map,
        no_hit_rgb,
    }: Footer<'_>,
) -> ImageGestures {
    let pixels_per_point = ui.ctx().pixels_per_point();
    let available = ui.available_size();
    let max_texture_side = ui.ctx().input(|i| i.max_texture_side);
    let mut gestures = ImageGestures {
        wanted_px: image_size_px(available, pixels_per_point, max_texture_side),
        ..ImageGestures::default()
    };
    let half = half_points(available);
    ui.horizontal_top(|ui| {
        ui.spacing_mut().item_spacing.x = IMAGE_GAP_POINTS;
        let captions = match shown {
            Some(images) => [
                "colour".to_owned(),
                format!(
                    "depth  (t {} near … {} far)",
                    short_number(images.depth_range.min_t),
                    short_number(images.depth_range.max_t)
                ),
            ],
            None => ["colour".to_owned(), "depth".to_owned()],
        };
        for (index, caption) in captions.into_iter().enumerate() {
            ui.vertical(|ui| {
                ui.set_width(half.x);
                ui.label(caption);
                let (area, response) = ui.allocate_exact_size(half, Sense::click_and_drag());
                let label = IMAGE_LABELS[index];
                response.widget_info(|| {
                    egui::WidgetInfo::labeled(egui::Role::Image, true, label.to_owned())
                });
                match shown {
                    None => {
                        ui.painter().rect_filled(area, 0.0, Color32::from_gray(30));
                    }
                    Some(images) => {
                        let texture = if index == 0 {
                            images.colour
                        } else {
                            images.depth
                        };
                        let rect = image_rect(area, images.size_px, pixels_per_point);
                        ui.painter().image(
                            texture.id(),
                            rect,
                            Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                            Color32::WHITE,
                        );
                        if let Some(pin) = pinned {
                            let at = pos_of_image_px(pin, rect, images.size_px);
                            ui.painter()
                                .circle_stroke(at, 5.0, Stroke::new(2.0, Color32::BLACK));
                            ui.painter()
                                .circle_stroke(at, 4.0, Stroke::new(1.5, Color32::WHITE));
                        }
                        read_gestures(ui, &response, rect, images.size_px, &mut gestures);
                    }
                }
                if index == 0 {
                    probe_ui(ui, probe_lines, pinned.is_some(), &mut gestures);
                } else {
                    let histogram = shown.and_then(|s| s.histogram);
                    gestures.depth_range_dragged =
                        histogram_ui(ui, histogram, depth_range, colour_map, no_hit_rgb);
                }
            });
        }
    });
    gestures
}

/// Where a frame of `size_px` is drawn in `area`: scaled to fit, square pixels, snapped to the
/// physical pixel grid so a 1:1 frame is shown without resampling.
fn image_rect(area: Rect, size_px: [u32; 2], pixels_per_point: f32) -> Rect {
    let frame_points = Vec2::new(size_px[0] as f32, size_px[1] as f32) / pixels_per_point;
    let scale = (area.width() / frame_points.x).min(area.height() / frame_points.y);
    let min = ((area.min.to_vec2() * pixels_per_point).round() / pixels_per_point).to_pos2();
    Rect::from_min_size(min, frame_points * scale)
}

/// Reads drags, wheel, pinch, hover and clicks on one image into `gestures`.
fn read_gestures(
    ui: &Ui,
    response: &egui::Response,
    rect: Rect,
    size_px: [u32; 2],
    gestures: &mut ImageGestures,
) {
    let px_per_point = DVec2::new(
        f64::from(size_px[0]) / f64::from(rect.width()),
        f64::from(size_px[1]) / f64::from(rect.height()),
    );
    let on_image = |pos: Pos2| rect.contains(pos).then(|| image_px_of(pos, rect, size_px));
    if response.dragged() {
        let delta = response.drag_delta();
        let delta_points = DVec2::new(f64::from(delta.x), -f64::from(delta.y));
        let shift = ui.input(|i| i.modifiers.shift);
        if response.dragged_by(PointerButton::Secondary)
            || (response.dragged_by(PointerButton::Primary) && shift)
        {
            gestures.orbit_points += delta_points;
        } else {
            gestures.pan_px += delta_points * px_per_point;
        }
    }
    let hover = response.hover_pos().and_then(on_image);
    if let Some(anchor) = hover {
        gestures.hover_px = Some(anchor);
        let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
        let factor = (-f64::from(scroll) / SCROLL_POINTS_PER_DOUBLING).exp2() / f64::from(pinch);
        if factor != 1.0 && factor.is_finite() {
            gestures.zoom = Some((factor, anchor));
        }
    }
    if response.clicked() {
        gestures.clicked_px = response.interact_pointer_pos().and_then(on_image);
    }
}

/// The probe's lines under the colour image, and an "Unpin" button while a pixel is pinned.
fn probe_ui(ui: &mut Ui, lines: &[String], pinned: bool, gestures: &mut ImageGestures) {
    let (rect, _) = ui.allocate_exact_size(
        Vec2::new(ui.available_width(), FOOTER_POINTS - 4.0),
        Sense::hover(),
    );
    let mut child = ui.new_child(egui::UiBuilder::new().max_rect(rect));
    // The button first, so it stays put while the hover lines come and go.
    if pinned
        && child
            .small_button("Unpin")
            .on_hover_text("Escape unpins too")
            .clicked()
    {
        gestures.unpin = true;
    }
    if lines.is_empty() {
        child.weak("hover an image to probe a pixel; click to pin it");
    }
    for line in lines {
        child.add(
            egui::Label::new(RichText::new(line).monospace().size(PROBE_FONT_POINTS)).truncate(),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn render_size_follows_physical_pixels() {
        // 808 points wide: two images of (808 − 8) / 2 = 400 points; the height is what the
        // caption and the footer leave.
        let height = 600.0 + CAPTION_POINTS + FOOTER_POINTS;
        let area = Vec2::new(808.0, height);
        assert_eq!(image_size_px(area, 1.0, 8192), (400, 600));
        assert_eq!(image_size_px(area, 2.0, 8192), (800, 1200));
        assert_eq!(image_size_px(area, 1.5, 8192), (600, 900));
        // Never larger than a texture may be, never empty.
        assert_eq!(image_size_px(area, 2.0, 1000), (800, 1000));
        assert_eq!(image_size_px(Vec2::ZERO, 1.0, 8192), (1, 1));
    }

    #[test]
    fn pointer_positions_map_to_image_pixels_y_up() {
        let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(100.0, 50.0));
        let size = [200, 100];
        assert_eq!(image_px_of(rect.left_bottom(), rect, size), DVec2::ZERO);
        assert_eq!(
            image_px_of(rect.right_top(), rect, size),
            DVec2::new(200.0, 100.0)
        );
        let px = DVec2::new(50.0, 25.0);
        let back = image_px_of(pos_of_image_px(px, rect, size), rect, size);
        assert!((back - px).length() < 1e-3);
    }
}
