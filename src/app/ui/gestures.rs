//! Pointer input on the two images, read into [`ImageGestures`] in image pixels (y up): the
//! camera's gestures (drag to pan, wheel to zoom, right- or Shift-drag to orbit), the
//! magnifier's (Ctrl+wheel or pinch to magnify, Ctrl- or middle-drag to move it), hover and
//! clicks.

use egui::{PointerButton, Pos2, Rect, Ui};
use glam::DVec2;

use super::magnifier::Region;

/// Scrolling this many points zooms by a factor of two.
const SCROLL_POINTS_PER_DOUBLING: f64 = 240.0;

/// Orbit angle per point of drag, radians (a drag across 300 points turns about 90°).
pub const ORBIT_RAD_PER_POINT: f64 = std::f64::consts::FRAC_PI_2 / 300.0;

/// Pointer input on the images, in image pixels with y up (see [`crate::app::navigate`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ImageGestures {
    /// Image size in physical pixels the area asks for.
    pub(crate) wanted_px: (u32, u32),
    /// Primary drag: the picture should follow by this many pixels.
    pub(crate) pan_px: DVec2,
    /// Secondary drag, or a primary drag with Shift: orbit by these many points (x right, y up).
    pub(crate) orbit_points: DVec2,
    /// Wheel zoom of the camera: size factor (< 1 zooms in) and the anchor pixel.
    pub(crate) zoom: Option<(f64, DVec2)>,
    /// Ctrl+wheel or pinch: magnification factor (> 1 enlarges) and the anchor pixel.
    pub(crate) magnify: Option<(f64, DVec2)>,
    /// Ctrl- or middle-drag: move the magnified region by these many image pixels.
    pub(crate) magnifier_pan_px: DVec2,
    /// The pointer's position on the image, if it is over one.
    pub(crate) hover_px: Option<DVec2>,
    /// A click (no drag) on an image pins this position.
    pub(crate) clicked_px: Option<DVec2>,
    /// "Unpin" was clicked.
    pub(crate) unpin: bool,
    /// "Trace" was clicked.
    pub(crate) trace: bool,
    /// A histogram handle moved the depth range.
    pub(crate) depth_range_dragged: bool,
}

/// Reads drags, wheel, pinch, hover and clicks on one image (the `region` of the frame drawn in
/// `rect`) into `gestures`.
pub(crate) fn read_gestures(
    ui: &Ui,
    response: &egui::Response,
    rect: Rect,
    region: Region,
    gestures: &mut ImageGestures,
) {
    let px_per_point = DVec2::new(
        region.size.x / f64::from(rect.width()),
        region.size.y / f64::from(rect.height()),
    );
    let on_image = |pos: Pos2| rect.contains(pos).then(|| region.image_px_of(pos, rect));
    let modifiers = ui.input(|i| i.modifiers);
    if response.dragged() {
        let delta = response.drag_delta();
        let delta_points = DVec2::new(f64::from(delta.x), -f64::from(delta.y));
        if response.dragged_by(PointerButton::Middle)
            || (response.dragged_by(PointerButton::Primary) && modifiers.command)
        {
            // The magnified region follows the pointer (so the picture moves with it).
            gestures.magnifier_pan_px -= delta_points * px_per_point;
        } else if response.dragged_by(PointerButton::Secondary)
            || (response.dragged_by(PointerButton::Primary) && modifiers.shift)
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
        let wheel = (f64::from(scroll) / SCROLL_POINTS_PER_DOUBLING).exp2();
        if modifiers.command || pinch != 1.0 {
            // egui turns Ctrl+wheel into a zoom delta; a pinch is one too.
            let factor = if pinch != 1.0 {
                f64::from(pinch)
            } else {
                wheel
            };
            if factor != 1.0 && factor.is_finite() {
                gestures.magnify = Some((factor, anchor));
            }
        } else if wheel != 1.0 && wheel.is_finite() {
            gestures.zoom = Some((1.0 / wheel, anchor));
        }
    }
    if response.clicked() {
        gestures.clicked_px = response.interact_pointer_pos().and_then(on_image);
    }
}
