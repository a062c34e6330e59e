//! The fast path: spheres projected to screen discs, binned into bands of rows, rasterised band
//! by band in parallel.
//!
//! Each sphere's centre is moved into camera space once per frame, in f64 and relative to the
//! camera centre, so coordinates of 1e7 cost no precision. For a pixel at screen (u, v) and a disc
//! (c_u, c_v, r) the test is `du² + dv² ≤ r²` with `du = u − c_u`, `dv = v − c_v` — the same
//! expression everywhere, so hit/miss is decided once — and the visible depth is
//! `t = c_w − √(r² − du² − dv²)` (tmin = −∞: the front root even behind the camera centre).
//!
//! Cost: a disc is listed in the bands its rows touch; within a row only the columns its chord can
//! cover are tested. A frame costs in proportion to the discs plus the pixels they cover, not to
//! pixels × spheres. Ties keep the sphere that comes first in the file (bands list discs in file
//! order and a hit replaces the current one only when strictly nearer; drawn front to back, a
//! hit at an equal t replaces it only for a sphere earlier in the file).
//!
//! Everything is f64: an f32 mode was measured slower than f64 and less exact, and removed
//! (`docs/accuracy.md`).
//!
//! * [`screen_disc`]: a sphere as a [`Disc`] on the screen
//! * [`projection`]: a scene's spheres projected ([`project_discs`]), with their depths
//! * [`bins`]: listing each disc in the bands of rows it touches; row and column spans
//! * [`hit`]: the pixel–disc test and its tie rule, once for one pixel and for four SIMD lanes;
//!   the visible hit among discs ([`nearest_hit`])
//! * [`chord`]: a disc's chord on a row, a band's discs gathered
//! * [`depth_order`]: discs sorted front to back, and the nearest ones that cover the image
//! * [`depth_sort`]: a pass's kept discs ordered by depth slice, in parallel
//! * [`placed`]: discs placed on the image (rows, columns, nearest t) and binned, in parts
//! * [`coarse_depth`]: discs behind what the nearest ones drew, culled frame-wide
//! * [`tiles`]: dense scenes drawn front to back tile by tile, each tile stopping where the rest
//!   is hidden
//! * [`raster`]: filling a band's pixels, and a whole frame
//! * [`strips`]: a frame drawn and handed on a strip of rows at a time
//! * [`shade`]: colours from the visible spheres

mod bins;
mod chord;
mod coarse_depth;
mod depth_order;
mod depth_sort;
mod hit;
mod placed;
mod projection;
mod raster;
mod screen_disc;
mod shade;
mod strips;
mod tiles;

pub(crate) use bins::pixel_span;
pub use hit::nearest_hit;
pub use projection::project_discs;
pub(crate) use projection::{draws_in_file_order, project_discs_with_depths};
pub(crate) use raster::rasterise_frame;
pub use screen_disc::Disc;
pub(crate) use shade::Palette;
#[cfg(feature = "oracle")]
pub(crate) use shade::frame_from_hits;
pub(crate) use strips::{STRIP_ROWS, Strip, rasterise_strips};
