//! The magnifier, as image viewers have it (tev): the rendered images themselves enlarged, both
//! together, with nearest-neighbour pixels and a pixel grid once pixels are large — without a
//! new render. The camera's zoom (the wheel) is another thing: it changes the view and renders
//! again. The magnifier shows a region of the frame: its centre and its zoom (1 = the whole
//! frame).

use egui::{Color32, Painter, Pos2, Rect, Stroke};
use glam::DVec2;

/// Largest magnification: one image pixel over 64 screen pixels at most.
pub(crate) const MAX_MAGNIFICATION: f64 = 64.0;

/// Grid lines are drawn once an image pixel is at least this many points wide.
const GRID_FROM_POINTS: f32 = 8.0;

/// Which part of the frame the images show.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Magnifier {
    /// 1 shows the whole frame; 4 shows a quarter of its width.
    pub zoom: f64,
    /// The image point (pixels from the bottom-left corner) at the centre of what is shown, as a
    /// share of the frame's size (so it survives a resize): (0.5, 0.5) is the frame's centre.
    pub centre: DVec2,
}

impl Default for Magnifier {
    fn default() -> Self {
        Self {
            zoom: 1.0,
            centre: DVec2::splat(0.5),
        }
    }
}

/// A region of a frame in image pixels (y up): `min` is its bottom-left corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Region {
    pub(crate) min: DVec2,
    pub(crate) size: DVec2,
}

impl Magnifier {
    /// Whether the images are enlarged.
    pub fn is_magnified(&self) -> bool {
        self.zoom > 1.0
    }

    /// The region of a frame of `size_px` shown (inside the frame).
    pub(crate) fn region(&self, size_px: [u32; 2]) -> Region {
        let frame = DVec2::new(f64::from(size_px[0]), f64::from(size_px[1]));
        let size = frame / self.zoom.max(1.0);
        let centre = self.centre * frame;
        let min = (centre - 0.5 * size).clamp(DVec2::ZERO, frame - size);
        Region { min, size }
    }

    /// Magnifies by `factor` keeping image point `anchor_px` where it is on screen.
    pub(crate) fn zoom_at(&mut self, factor: f64, anchor_px: DVec2, size_px: [u32; 2]) {
        if !(factor.is_finite() && factor > 0.0) {
            return;
        }
        let frame = DVec2::new(f64::from(size_px[0]), f64::from(size_px[1]));
        let before = self.region(size_px);
        let zoom = (self.zoom * factor).clamp(1.0, MAX_MAGNIFICATION);
        // The anchor keeps its share of the shown region.
        let share = (anchor_px - before.min) / before.size;
        let size = frame / zoom;
        let min = anchor_px - share * size;
        self.zoom = zoom;
        self.centre = (min + 0.5 * size) / frame;
        let region = self.region(size_px);
        self.centre = (region.min + 0.5 * region.size) / frame;
    }

    /// Moves what is shown by `delta_px` image pixels.
    pub(crate) fn pan(&mut self, delta_px: DVec2, size_px: [u32; 2]) {
        let frame = DVec2::new(f64::from(size_px[0]), f64::from(size_px[1]));
        if delta_px.is_finite() {
            self.centre += delta_px / frame;
            let region = self.region(size_px);
            self.centre = (region.min + 0.5 * region.size) / frame;
        }
    }
}

impl Region {
    /// The texture coordinates (top row first) of the region.
    pub(crate) fn uv(&self, size_px: [u32; 2]) -> Rect {
        let (w, h) = (f64::from(size_px[0]), f64::from(size_px[1]));
        Rect::from_min_max(
            Pos2::new(
                (self.min.x / w) as f32,
                (1.0 - (self.min.y + self.size.y) / h) as f32,
            ),
            Pos2::new(
                ((self.min.x + self.size.x) / w) as f32,
                (1.0 - self.min.y / h) as f32,
            ),
        )
    }

    /// The image point (pixels, y up) under screen position `pos` of the region drawn in `rect`.
    pub(crate) fn image_px_of(&self, pos: Pos2, rect: Rect) -> DVec2 {
        DVec2::new(
            self.min.x + f64::from((pos.x - rect.min.x) / rect.width()) * self.size.x,
            self.min.y + f64::from((rect.max.y - pos.y) / rect.height()) * self.size.y,
        )
    }

    /// Where image point `px` is drawn in `rect`.
    pub(crate) fn pos_of_image_px(&self, px: DVec2, rect: Rect) -> Pos2 {
        Pos2::new(
            rect.min.x + ((px.x - self.min.x) / self.size.x) as f32 * rect.width(),
            rect.max.y - ((px.y - self.min.y) / self.size.y) as f32 * rect.height(),
        )
    }

    /// Draws the boundaries between image pixels over the region drawn in `rect`, once pixels
    /// are large enough for them to help.
    pub(crate) fn paint_grid(&self, painter: &Painter, rect: Rect) {
        let points_per_pixel = rect.width() / self.size.x as f32;
        if points_per_pixel < GRID_FROM_POINTS {
            return;
        }
        let stroke = Stroke::new(1.0, Color32::from_black_alpha(90));
        let mut x = self.min.x.floor() + 1.0;
        while x < self.min.x + self.size.x {
            let at = self.pos_of_image_px(DVec2::new(x, self.min.y), rect).x;
            painter.line_segment(
                [Pos2::new(at, rect.top()), Pos2::new(at, rect.bottom())],
                stroke,
            );
            x += 1.0;
        }
        let mut y = self.min.y.floor() + 1.0;
        while y < self.min.y + self.size.y {
            let at = self.pos_of_image_px(DVec2::new(self.min.x, y), rect).y;
            painter.line_segment(
                [Pos2::new(rect.left(), at), Pos2::new(rect.right(), at)],
                stroke,
            );
            y += 1.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_whole_frame_at_zoom_one_and_the_anchor_stays_put() {
        let size = [200, 100];
        let mut magnifier = Magnifier::default();
        let whole = magnifier.region(size);
        assert_eq!(whole.min, DVec2::ZERO);
        assert_eq!(whole.size, DVec2::new(200.0, 100.0));
        let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), egui::vec2(400.0, 200.0));
        let anchor = DVec2::new(150.0, 30.0);
        let on_screen = whole.pos_of_image_px(anchor, rect);
        magnifier.zoom_at(4.0, anchor, size);
        let region = magnifier.region(size);
        assert_eq!(region.size, DVec2::new(50.0, 25.0));
        let after = region.image_px_of(on_screen, rect);
        assert!((after - anchor).length() < 1e-3, "{after} against {anchor}");
        // Never outside the frame, never below 1.
        magnifier.pan(DVec2::new(1e6, -1e6), size);
        let region = magnifier.region(size);
        assert!(region.min.x + region.size.x <= 200.0 && region.min.y >= 0.0);
        magnifier.zoom_at(1e-9, anchor, size);
        assert_eq!(magnifier.zoom, 1.0);
    }

    #[test]
    fn texture_coordinates_run_top_row_first() {
        let region = Region {
            min: DVec2::new(50.0, 0.0),
            size: DVec2::new(50.0, 25.0),
        };
        let uv = region.uv([100, 100]);
        assert_eq!(uv.min, Pos2::new(0.5, 0.75));
        assert_eq!(uv.max, Pos2::new(1.0, 1.0));
    }
}
