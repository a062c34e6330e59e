//! Measuring a claim on their picture beside the exact one (`tests/statements.rs`): centroids and
//! second moments of what is lit, flips and mirrors, grey against the exact t, and which sphere
//! each pixel shows.
#![allow(dead_code)]

use glam::DVec2;
use image::RgbImage;

use super::cases::Pictures;
use super::claims::Claim;
use super::shapes::{differing, flipped, least_squares, mirrored, shape, transposed};

pub(crate) fn near(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance
}

/// The share of `pixels` for which `holds` is true (0 with no pixels).
pub(crate) fn share(pixels: &[(u32, u32)], holds: impl Fn(u32, u32) -> bool) -> f64 {
    if pixels.is_empty() {
        return 0.0;
    }
    pixels.iter().filter(|&&(x, row)| holds(x, row)).count() as f64 / pixels.len() as f64
}

pub(crate) fn grey(image: &RgbImage, x: u32, row: u32) -> f64 {
    f64::from(image.get_pixel(x, row).0[0])
}

/// The course's depth grey of `t` over white `white` … black `black`.
pub(crate) fn course_grey(t: f64, white: f64, black: f64) -> f64 {
    (255.0 * (black - t) / (black - white))
        .floor()
        .clamp(0.0, 255.0)
}

/// Measures `claim` on `p`: Ok when the picture shows it.
pub(crate) fn measure(claim: &Claim, p: &Pictures) -> Result<(), String> {
    let check = |ok: bool, what: String| if ok { Ok(()) } else { Err(what) };
    let (min_t, max_t) = (p.view.depth_range.min_t, p.view.depth_range.max_t);
    match *claim {
        Claim::Shifted { right, up } => {
            let (_, theirs, _) = shape(&p.colour);
            let (_, exact, _) = shape(&p.exact_colour);
            let moved = theirs - exact;
            check(
                near(moved.x, right, 0.04) && near(moved.y, up, 0.04),
                format!("moved {moved:?}, said right {right} up {up}"),
            )
        }
        Claim::Zoomed { out, width } => {
            let (area, ..) = shape(&p.colour);
            let (exact_area, ..) = shape(&p.exact_colour);
            let ratio = (area / exact_area).sqrt();
            check(
                (ratio < 0.98) == out
                    && (ratio > 1.02) != out
                    && width.is_none_or(|w| near(ratio, w, 0.02 * w)),
                format!("spheres {ratio}× as wide, said out {out}, {width:?}"),
            )
        }
        Claim::Ellipse { wide, tall } => {
            let (_, _, spread) = shape(&p.colour);
            let (_, _, exact) = shape(&p.exact_colour);
            let ratio = spread / exact;
            check(
                near(ratio.x, wide, 0.02 * wide) && near(ratio.y, tall, 0.02 * tall),
                format!("drawn {ratio:?} as wide and tall, said {wide} {tall}"),
            )
        }
        Claim::LongerAlongLonger => {
            let (w, h) = p.size();
            let (_, _, spread) = shape(&p.colour);
            let longer = if w > h {
                spread.x / spread.y
            } else {
                spread.y / spread.x
            };
            check(longer > 1.05, format!("longer side over shorter {longer}"))
        }
        Claim::UpsideDown => check_like(p, &flipped(&p.exact_colour), &flipped(&p.exact_depth)),
        Claim::MirroredLeftRight => {
            check_like(p, &mirrored(&p.exact_colour), &mirrored(&p.exact_depth))
        }
        Claim::Transposed => {
            check_like(p, &transposed(&p.exact_colour), &transposed(&p.exact_depth))
        }
        Claim::Axes(m) => {
            let (w, h) = p.size();
            // Pixel indices: the image's centre is at (W − 1)/2, (H − 1)/2.
            let centre = (DVec2::new(f64::from(w), f64::from(h)) - 1.0) / 2.0;
            let (_, theirs, _) = shape(&p.colour);
            let (_, exact, _) = shape(&p.exact_colour);
            let expected = m.inverse() * (exact - centre) + centre;
            check(
                (theirs - expected).length() <= 0.15,
                format!("disc at {theirs:?}, the axes said put it at {expected:?}"),
            )
        }
        Claim::NearBlackFarWhite => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, row)| (min_t..max_t).contains(&p.t(x, row)))
                .collect();
            let n = pixels.len() as f64;
            let mean_t = pixels.iter().map(|&(x, r)| p.t(x, r)).sum::<f64>() / n;
            let mean_g = pixels
                .iter()
                .map(|&(x, r)| grey(&p.depth, x, r))
                .sum::<f64>()
                / n;
            let covariance: f64 = pixels
                .iter()
                .map(|&(x, r)| (p.t(x, r) - mean_t) * (grey(&p.depth, x, r) - mean_g))
                .sum();
            check(
                covariance > 0.0 && n > 100.0,
                format!("grey against t: {covariance} over {n} px"),
            )
        }
        Claim::DepthNoHit(bytes) => {
            let pixels = p.no_hit_pixels();
            let held = share(&pixels, |x, row| p.depth.get_pixel(x, row).0 == bytes);
            check(
                held >= 0.99,
                format!("{held} of the no-hit pixels are {bytes:?}"),
            )
        }
        Claim::SceneBackground(bytes) => check(
            p.scene_background() == bytes,
            format!("the scene's background is {:?}", p.scene_background()),
        ),
        Claim::Background(theirs, scene) => {
            let pixels = p.no_hit_pixels();
            let held = share(&pixels, |x, row| p.colour.get_pixel(x, row).0 == theirs);
            check(
                held >= 0.99 && p.scene_background() == scene,
                format!(
                    "{held} of the no-hit pixels are {theirs:?}; scene {:?}",
                    p.scene_background()
                ),
            )
        }
        Claim::Ramp { white, black } => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, row)| {
                    let t = p.t(x, row);
                    t > white.min(black) && t < white.max(black)
                })
                .collect();
            let held = share(&pixels, |x, row| {
                near(
                    grey(&p.depth, x, row),
                    course_grey(p.t(x, row), white, black),
                    1.0,
                )
            });
            check(
                held >= 0.99 && pixels.len() > 50,
                format!(
                    "{held} of {} pixels drawn white at {white}, black at {black}",
                    pixels.len()
                ),
            )
        }
        Claim::Extremes {
            near_t,
            near_grey,
            far_t,
            far_grey,
        } => {
            let pixels = p.hit_pixels();
            let at = |pick: fn(f64, f64) -> bool| {
                let mut best = pixels[0];
                for &(x, row) in &pixels {
                    if pick(p.t(x, row), p.t(best.0, best.1)) {
                        best = (x, row);
                    }
                }
                (p.t(best.0, best.1), grey(&p.depth, best.0, best.1))
            };
            let (t0, g0) = at(|a, b| a < b);
            let (t1, g1) = at(|a, b| a > b);
            check(
                near(t0, near_t, 1e-3 * near_t.abs().max(1.0))
                    && near(g0, near_grey, 1.0)
                    && near(t1, far_t, 1e-3 * far_t.abs().max(1.0))
                    && near(g1, far_grey, 1.0),
                format!("nearest t {t0} grey {g0}, farthest t {t1} grey {g1}"),
            )
        }
        Claim::TRamp { right, up } => {
            // Their t from their grey (the middle of its level) less the exact t, fitted as
            // a·u + b·v + c by least squares.
            let width = max_t - min_t;
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| (1.0..254.0).contains(&grey(&p.depth, x, r)))
                .collect();
            let rows: Vec<([f64; 3], f64)> = pixels
                .iter()
                .map(|&(x, r)| {
                    let theirs = max_t - (grey(&p.depth, x, r) + 0.5) / 255.0 * width;
                    let s = p.screen(x, r);
                    ([s.x, s.y, 1.0], theirs - p.t(x, r))
                })
                .collect();
            let [a, b, _] = least_squares(&rows);
            let slack = |said: f64| 0.05 + 0.1 * said.abs();
            check(
                pixels.len() > 100 && near(a, right, slack(right)) && near(b, up, slack(up)),
                format!("t grows {a} right, {b} up over {} px", pixels.len()),
            )
        }
        Claim::FileOrder { last } => {
            let (w, h) = p.size();
            let mut telling = 0;
            let mut held = 0;
            for row in 0..h {
                for x in 0..w {
                    let hits = p.all_hits(x, row);
                    if hits.len() < 2 {
                        continue;
                    }
                    let in_order = if last { hits[hits.len() - 1] } else { hits[0] };
                    let nearest = hits
                        .iter()
                        .copied()
                        .fold(hits[0], |a, b| if b.1 < a.1 { b } else { a });
                    if p.sphere_bytes(in_order.0) == p.sphere_bytes(nearest.0) {
                        continue;
                    }
                    telling += 1;
                    held += usize::from(p.colour.get_pixel(x, row).0 == p.sphere_bytes(in_order.0));
                }
            }
            check(
                telling >= 20 && held as f64 >= 0.99 * f64::from(telling),
                format!("{held} of {telling} telling pixels show the sphere in file order"),
            )
        }
        Claim::Block(columns, rows) => {
            let (w, h) = p.size();
            let background = p.scene_background();
            let mut outside_ok = true;
            let mut inside_lit = 0;
            for row in 0..h {
                for x in 0..w {
                    let y_up = h - 1 - row;
                    let colour = p.colour.get_pixel(x, row).0;
                    if x >= columns || y_up >= rows {
                        outside_ok &= colour == background;
                    } else {
                        inside_lit += usize::from(colour != background);
                    }
                }
            }
            let exact_outside = (0..h).any(|row| {
                (0..w).any(|x| {
                    (x >= columns || h - 1 - row >= rows)
                        && p.exact_colour.get_pixel(x, row).0 != background
                })
            });
            check(
                outside_ok && inside_lit > 0 && exact_outside,
                format!("outside the block background: {outside_ok}, inside lit {inside_lit}"),
            )
        }
        Claim::LostBefore(t) => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| p.t(x, r) < t)
                .collect();
            let lost = share(&pixels, |x, r| {
                p.colour.get_pixel(x, r) != p.exact_colour.get_pixel(x, r)
                    || p.depth.get_pixel(x, r) != p.exact_depth.get_pixel(x, r)
            });
            let kept = share(&p.hit_pixels(), |x, r| {
                p.t(x, r) >= t && p.colour.get_pixel(x, r) == p.exact_colour.get_pixel(x, r)
            });
            check(
                pixels.len() >= 20 && lost >= 0.95 && kept > 0.0,
                format!("{lost} of {} pixels before t = {t} lost", pixels.len()),
            )
        }
        Claim::OneLevelBrighter => {
            let mut brighter = 0;
            let mut other = 0;
            for (a, b) in p.colour.pixels().zip(p.exact_colour.pixels()) {
                for (&theirs, &exact) in a.0.iter().zip(&b.0) {
                    match i16::from(theirs) - i16::from(exact) {
                        0 => {}
                        1 => brighter += 1,
                        _ => other += 1,
                    }
                }
            }
            check(
                brighter > 0 && other == 0,
                format!("{brighter} one brighter, {other} otherwise"),
            )
        }
        Claim::Farther => {
            let pixels = p.hit_pixels();
            let never_nearer = pixels
                .iter()
                .all(|&(x, r)| grey(&p.depth, x, r) <= grey(&p.exact_depth, x, r));
            let farther = share(&pixels, |x, r| {
                grey(&p.depth, x, r) < grey(&p.exact_depth, x, r)
            });
            check(
                never_nearer && farther >= 0.5,
                format!("nearer nowhere: {never_nearer}, farther {farther}"),
            )
        }
        Claim::Striped => {
            let beyond = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| !(min_t..=max_t).contains(&p.t(x, r)))
                .filter(|&(x, r)| !matches!(grey(&p.depth, x, r) as u8, 0 | 255))
                .count();
            check(
                beyond >= 20,
                format!("{beyond} pixels beyond the range neither white nor black"),
            )
        }
        Claim::NearerThanMinBlack => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| p.t(x, r) < min_t)
                .collect();
            let black = share(&pixels, |x, r| grey(&p.depth, x, r) == 0.0);
            check(
                pixels.len() >= 20 && black >= 0.99,
                format!("{black} of {} black", pixels.len()),
            )
        }
        Claim::LaterWinsTie => {
            let (w, h) = p.size();
            let (mut ties, mut later) = (0, 0);
            for row in 0..h {
                for x in 0..w {
                    let hits = p.all_hits(x, row);
                    let nearest = hits.iter().map(|h| h.1).fold(f64::INFINITY, f64::min);
                    let tied: Vec<usize> = hits
                        .iter()
                        .filter(|h| h.1 == nearest)
                        .map(|h| h.0)
                        .collect();
                    if tied.len() < 2
                        || p.sphere_bytes(tied[0]) == p.sphere_bytes(tied[tied.len() - 1])
                    {
                        continue;
                    }
                    ties += 1;
                    later += usize::from(
                        p.colour.get_pixel(x, row).0 == p.sphere_bytes(tied[tied.len() - 1]),
                    );
                }
            }
            check(
                ties >= 20 && later == ties,
                format!("{later} of {ties} tied pixels show the later sphere"),
            )
        }
        Claim::VerticalByUp => {
            let camera = &p.scene.camera;
            let d = camera.direction_world.normalize();
            let across = (camera.up_world - camera.up_world.dot(d) * d).length();
            let (_, _, spread) = shape(&p.colour);
            let (_, _, exact) = shape(&p.exact_colour);
            let ratio = spread.y / exact.y;
            check(
                near(ratio, 1.0 / across, 0.03) && !near(across, 1.0, 0.02),
                format!("{ratio}× as tall, up across the direction {across}"),
            )
        }
        Claim::DividedByDirection => {
            let length = p.scene.camera.direction_world.length();
            let pixels = p.hit_pixels();
            let held = share(&pixels, |x, r| {
                near(
                    grey(&p.depth, x, r),
                    course_grey(p.t(x, r) / length, min_t, max_t),
                    1.0,
                )
            });
            check(
                held >= 0.99 && length != 1.0,
                format!("{held} drawn from t/|direction|"),
            )
        }
        Claim::MapsAbsZ => {
            let (d, horizontal, up, _) = p.basis();
            let pixels = p.hit_pixels();
            let held = share(&pixels, |x, r| {
                let s = p.screen(x, r);
                let hit = p.scene.camera.center_world + s.x * horizontal + s.y * up + p.t(x, r) * d;
                near(
                    grey(&p.depth, x, r),
                    course_grey(hit.z.abs(), min_t, max_t),
                    1.0,
                )
            });
            check(held >= 0.99, format!("{held} drawn from |z|"))
        }
        Claim::OutsideColour(bytes) => {
            let pixels: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| !(min_t..=max_t).contains(&p.t(x, r)))
                .collect();
            let held = share(&pixels, |x, r| p.depth.get_pixel(x, r).0 == bytes);
            check(
                pixels.len() >= 20 && held >= 0.99,
                format!("{held} of {} outside are {bytes:?}", pixels.len()),
            )
        }
        Claim::SilhouettesGrow => {
            let lit =
                |image: &RgbImage, x: u32, r: u32| *image.get_pixel(x, r) != *image.get_pixel(0, 0);
            let exact_lit: Vec<(u32, u32)> = p
                .hit_pixels()
                .into_iter()
                .filter(|&(x, r)| lit(&p.exact_colour, x, r))
                .collect();
            let kept = share(&exact_lit, |x, r| lit(&p.colour, x, r));
            let (theirs, ..) = shape(&p.colour);
            check(
                kept >= 0.99 && theirs > exact_lit.len() as f64,
                format!(
                    "{kept} of the exact silhouettes kept, {theirs} px lit against {}",
                    exact_lit.len()
                ),
            )
        }
        Claim::DepthWrongWhereHit => {
            let wrong = share(&p.hit_pixels(), |x, r| {
                p.depth.get_pixel(x, r) != p.exact_depth.get_pixel(x, r)
            });
            let right = share(&p.no_hit_pixels(), |x, r| {
                p.depth.get_pixel(x, r) == p.exact_depth.get_pixel(x, r)
            });
            check(
                wrong >= 0.5 && right >= 0.99,
                format!("wrong at {wrong} of the hits, right at {right} of the rest"),
            )
        }
    }
}

/// Whether their pictures are `colour` and `depth` (a flip or mirror of the exact ones) to
/// within a few pixels, and not the exact ones.
pub(crate) fn check_like(p: &Pictures, colour: &RgbImage, depth: &RgbImage) -> Result<(), String> {
    let (w, h) = p.size();
    let allowed = (w * h / 200) as usize;
    let off = differing(&p.colour, colour) + differing(&p.depth, depth);
    let from_exact = differing(&p.colour, &p.exact_colour) + differing(&p.depth, &p.exact_depth);
    if off <= allowed && from_exact > 10 * allowed.max(1) {
        Ok(())
    } else {
        Err(format!(
            "{off} pixels off the picture said, {from_exact} off the exact one"
        ))
    }
}
