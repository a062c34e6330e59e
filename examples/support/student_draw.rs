//! The seeded draw of the generated corpus: a program of the student caster (`student.rs`) with
//! one to three knobs turned, with values that are not round.

use super::{DepthRule, Keep, NonSquare, OutsideRule, Program};

/// A seeded sequence (SplitMix64): the same programs on every machine.
pub(crate) struct Draw(u64);

impl Draw {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed)
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi), to three decimals (values not round, yet printable).
    pub(crate) fn value(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next() >> 11) as f64 / (1u64 << 53) as f64;
        ((lo + (hi - lo) * unit) * 1000.0).round() / 1000.0
    }

    pub(crate) fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

/// Knobs a draw can turn (a few per program).
const KNOBS: usize = 14;

/// A program with one to three knobs turned, drawn from `draw`; `non_square` says whether the
/// image it will render is non-square (the crop knobs need one).
pub(crate) fn draw_program(draw: &mut Draw, non_square: bool) -> Program {
    let mut program = Program::course();
    let turns = 1 + draw.below(3) as usize;
    let mut turned = Vec::new();
    while turned.len() < turns {
        let knob = draw.below(KNOBS as u64) as usize;
        if turned.contains(&knob) || (knob == 5 && !non_square) {
            continue;
        }
        turned.push(knob);
        match knob {
            0 => program.sample = (draw.value(0.05, 0.95), draw.value(0.05, 0.95)),
            1 => {
                let k = draw.value(0.8, 1.3);
                program.axis_lengths = (k, k);
            }
            2 => program.axis_lengths = (draw.value(0.8, 1.3), draw.value(0.8, 1.3)),
            3 => program.mirrored = true,
            4 => program.upside_down = true,
            5 => {
                program.non_square = match draw.below(3) {
                    0 => NonSquare::Stretched,
                    1 => NonSquare::BottomStrip,
                    _ => NonSquare::Block,
                }
            }
            6 => {
                program.keep = if draw.below(2) == 0 {
                    Keep::FirstInFile
                } else {
                    Keep::LastInFile
                }
            }
            7 => match draw.below(3) {
                0 => program.tmin = 0.0,
                1 => {
                    program.tmin = -1.0;
                    program.far_when_refused = false;
                }
                _ => {
                    program.tmin = 0.0;
                    program.far_when_refused = false;
                }
            },
            8 => {
                program.background = Some([
                    (draw.value(0.0, 1.0) * 255.0) as u8,
                    (draw.value(0.0, 1.0) * 255.0) as u8,
                    (draw.value(0.0, 1.0) * 255.0) as u8,
                ]);
            }
            9 => program.rounded = true,
            10 => {
                program.depth = match draw.below(4) {
                    0 => DepthRule::Reversed,
                    1 => DepthRule::PerImage {
                        near: 204.0,
                        far: 51.0,
                    },
                    2 => DepthRule::PerImage {
                        near: 255.0,
                        far: 0.0,
                    },
                    _ => DepthRule::IntegerRange,
                }
            }
            11 => {
                program.outside = if draw.below(2) == 0 {
                    OutsideRule::Wrap
                } else {
                    OutsideRule::Black
                }
            }
            12 => program.depth_no_hit_background = true,
            _ => program.up_along_direction = draw.value(0.1, 0.5),
        }
    }
    program
}
