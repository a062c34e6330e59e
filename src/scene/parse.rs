//! Recursive-descent parser: scene text → validated [`Scene`].
//!
//! The grammar is docs/spec.md's. Top-level blocks may come in any order, each at most once; the camera
//! is required. `MaterialIndex` applies to every following object in file order, across group
//! boundaries. Counts are checked against what the blocks hold (no allocation is sized by a count
//! from the file), numbers must be finite, and group nesting is capped at [`MAX_GROUP_DEPTH`].

use glam::{DVec3, Vec3};

use super::ahead::Ahead;
use super::error::{Location, ParseError, ParseErrorKind};
use super::lexer::{Lexer, Token};
use super::model::{DEFAULT_BACKGROUND, Material, OrthographicCamera, Scene, Sphere};
use crate::geometry::camera::{CameraBasis, CameraError};

/// Largest magnitude of a coordinate, radius or size: squares and sums of squares of such numbers
/// stay finite in f64, so no input can drive the arithmetic to infinity or NaN.
pub const MAX_MAGNITUDE: f64 = 1e150;

/// Smallest camera size: the pixels of a smaller view are so small (below about 1e-154 at the
/// largest image side) that their squares underflow, and every disc test would answer wrongly.
pub const MIN_VIEW_SIZE: f64 = 1e-150;

/// The UTF-8 byte-order mark some editors put at the start of a file; it is skipped.
pub(super) const BYTE_ORDER_MARK: char = '\u{feff}';

/// Whether a token looks like the start of a comment (the format has none).
fn looks_like_comment(text: &str) -> bool {
    text.starts_with('#') || text.starts_with("//")
}

/// Deepest group nesting accepted; deeper files get [`ParseErrorKind::TooDeep`].
pub const MAX_GROUP_DEPTH: usize = 256;

/// Keywords of the course's later assignments: named in a "not supported" error.
const UNSUPPORTED_KEYWORDS: &[&str] = &[
    "PerspectiveCamera",
    "Lights",
    "DirectionalLight",
    "PointLight",
    "AmbientLight",
    "ambientLight",
    "Plane",
    "Triangle",
    "TriangleMesh",
    "Transform",
    "Scale",
    "UniformScale",
    "Translate",
    "Rotate",
    "XRotate",
    "YRotate",
    "ZRotate",
    "Matrix",
    "Checkerboard",
    "Noise",
    "Marble",
    "Wood",
    "specularColor",
    "exponent",
    "reflectiveColor",
    "transparentColor",
    "indexOfRefraction",
    "angle",
];

/// Longest excerpt of a token quoted in an error message, in characters.
const MAX_QUOTED_CHARS: usize = 40;

/// Spheres parsed between two progress reports.
pub(super) const SPHERES_PER_REPORT: usize = 16_384;

/// Spheres listed before the list makes room for the rest of the text
/// ([`Parser::reserve_once_past_threshold`]: after a sphere, or before a run taken whole).
pub(super) const SPHERES_BEFORE_RESERVE: usize = 4_096;

/// Fewest bytes a sphere statement takes (`Sphere{center 0 0 0 radius 0}` is 30): the room made
/// for the rest of a text never exceeds what it could hold.
const MIN_SPHERE_BYTES: usize = 24;

/// Fewest bytes a `MaterialIndex` statement takes (`MaterialIndex 0` is 15).
const MIN_MATERIAL_INDEX_BYTES: usize = 15;

/// A token as quoted in an error: escaped and shortened.
fn quote(text: &str) -> String {
    let mut quoted: String = text.chars().take(MAX_QUOTED_CHARS).collect();
    if text.chars().count() > MAX_QUOTED_CHARS {
        quoted.push('…');
    }
    quoted.escape_debug().to_string()
}

fn error<T>(location: Location, kind: ParseErrorKind) -> Result<T, ParseError> {
    Err(ParseError::new(location, kind))
}

pub(super) struct Parser<'a> {
    pub(super) lexer: Lexer<'a>,
    /// The `MaterialIndex` in effect.
    pub(super) current_material: Option<u32>,
    /// Every `MaterialIndex` statement, checked against the materials at the end.
    pub(super) material_references: Vec<(u64, Location)>,
    pub(super) spheres: Vec<Sphere>,
    /// Told the share of the text parsed, every [`SPHERES_PER_REPORT`] spheres.
    pub(super) progress: &'a dyn Fn(f64),
    /// Runs of sphere statements parsed ahead on other threads, in file order ([`split`]).
    pub(super) ahead: std::collections::VecDeque<Ahead<'a>>,
    /// Byte offset where the file's spheres begin (the end of its first sphere statement, or the
    /// start of a run taken whole): the lists' room for the rest is judged from the text after
    /// it, not from a `Materials` block however large ([`Parser::reserve_for_the_rest`]).
    pub(super) spheres_from_byte: Option<usize>,
    /// Whether room for the rest of the text was made (once).
    pub(super) reserved: bool,
}

impl<'a> Parser<'a> {
    pub(super) fn new(text: &'a str, progress: &'a dyn Fn(f64)) -> Self {
        Self {
            lexer: Lexer::new(text),
            current_material: None,
            material_references: Vec::new(),
            spheres: Vec::new(),
            progress,
            ahead: std::collections::VecDeque::new(),
            spheres_from_byte: None,
            reserved: false,
        }
    }

    /// The next token; `expected` says what was expected should the file end here (made only
    /// then: no allocation per token).
    fn next(&mut self, expected: impl FnOnce() -> String) -> Result<Token<'a>, ParseError> {
        match self.lexer.next() {
            Some(token) => Ok(token),
            None => error(
                self.lexer.here(),
                ParseErrorKind::UnexpectedEnd {
                    expected: expected(),
                },
            ),
        }
    }

    fn unexpected<T>(token: Token<'_>, expected: &str) -> Result<T, ParseError> {
        let kind = if UNSUPPORTED_KEYWORDS.contains(&token.text) {
            ParseErrorKind::Unsupported {
                keyword: token.text.to_owned(),
            }
        } else if looks_like_comment(token.text) {
            ParseErrorKind::Comment {
                found: quote(token.text),
            }
        } else {
            ParseErrorKind::Expected {
                expected: expected.to_owned(),
                found: quote(token.text),
            }
        };
        error(token.location, kind)
    }

    /// Consumes `keyword` or fails with "expected 'keyword', found …".
    fn expect(&mut self, keyword: &str) -> Result<Token<'a>, ParseError> {
        let expected = || format!("'{keyword}'");
        let token = self.next(expected)?;
        if token.text == keyword {
            Ok(token)
        } else {
            Self::unexpected(token, &expected())
        }
    }

    fn number(&mut self, what: &'static str) -> Result<(f64, Location), ParseError> {
        let token = self.next(|| format!("a number ({what})"))?;
        match token.text.parse::<f64>() {
            Ok(value) if value.abs() <= MAX_MAGNITUDE => Ok((value, token.location)),
            Ok(value) if value.is_finite() => error(
                token.location,
                ParseErrorKind::OutOfRange {
                    what,
                    found: quote(token.text),
                },
            ),
            Ok(_) => error(
                token.location,
                ParseErrorKind::NotFinite {
                    what,
                    found: quote(token.text),
                },
            ),
            Err(_) if looks_like_comment(token.text) => error(
                token.location,
                ParseErrorKind::Comment {
                    found: quote(token.text),
                },
            ),
            Err(_) => error(
                token.location,
                ParseErrorKind::NotANumber {
                    what,
                    found: quote(token.text),
                },
            ),
        }
    }

    fn vector(&mut self, what: &'static str) -> Result<(DVec3, Location), ParseError> {
        let (x, location) = self.number(what)?;
        let (y, _) = self.number(what)?;
        let (z, _) = self.number(what)?;
        Ok((DVec3::new(x, y, z), location))
    }

    /// A colour channel: a number as any other (finite, at most 1e150), kept as a 32-bit float
    /// as the course's own parser did; beyond the 32-bit range it saturates (above 1 every
    /// channel shows full anyway).
    fn channel(&mut self, what: &'static str) -> Result<f32, ParseError> {
        let (value, _) = self.number(what)?;
        let largest = f64::from(f32::MAX);
        Ok(value.clamp(-largest, largest) as f32)
    }

    fn colour(&mut self, what: &'static str) -> Result<Vec3, ParseError> {
        Ok(Vec3::new(
            self.channel(what)?,
            self.channel(what)?,
            self.channel(what)?,
        ))
    }

    pub(super) fn count(&mut self, what: &'static str) -> Result<(u64, Location), ParseError> {
        let token = self.next(|| format!("a count ({what})"))?;
        match token.text.parse::<u64>() {
            Ok(value) => Ok((value, token.location)),
            Err(_) => error(
                token.location,
                ParseErrorKind::NotACount {
                    what,
                    found: quote(token.text),
                },
            ),
        }
    }

    pub(super) fn scene(mut self) -> Result<Scene, ParseError> {
        const TOP_LEVEL: &str = "'OrthographicCamera', 'Background', 'Materials' or 'Group'";
        let mut camera = None;
        let mut background = None;
        let mut materials: Option<Vec<Material>> = None;
        let mut group_seen = false;
        while let Some(token) = self.lexer.next() {
            let duplicate = |block| error(token.location, ParseErrorKind::Duplicate { block });
            match token.text {
                "OrthographicCamera" if camera.is_some() => return duplicate("OrthographicCamera"),
                "OrthographicCamera" => camera = Some(self.camera()?),
                "Background" if background.is_some() => return duplicate("Background"),
                "Background" => background = Some(self.background()?),
                "Materials" if materials.is_some() => return duplicate("Materials"),
                "Materials" => materials = Some(self.materials()?),
                "Group" if group_seen => return duplicate("Group"),
                "Group" => {
                    group_seen = true;
                    self.group(1)?;
                }
                _ => return Self::unexpected(token, TOP_LEVEL),
            }
        }
        let Some(camera) = camera else {
            if !(background.is_some() || materials.is_some() || group_seen) {
                return error(Location { line: 1, column: 1 }, ParseErrorKind::Empty);
            }
            return error(self.lexer.here(), ParseErrorKind::MissingCamera);
        };
        let materials = materials.unwrap_or_default();
        for &(index, location) in &self.material_references {
            if index >= materials.len() as u64 {
                return error(
                    location,
                    ParseErrorKind::MaterialIndexOutOfRange {
                        index,
                        count: materials.len(),
                    },
                );
            }
        }
        Ok(Scene {
            camera,
            background: background.unwrap_or(DEFAULT_BACKGROUND),
            materials,
            spheres: self.spheres,
        })
    }

    fn camera(&mut self) -> Result<OrthographicCamera, ParseError> {
        self.expect("{")?;
        self.expect("center")?;
        let (center_world, _) = self.vector("camera center")?;
        self.expect("direction")?;
        let (direction_world, direction_at) = self.vector("camera direction")?;
        let up_token = self.expect("up")?;
        let (up_world, _) = self.vector("camera up")?;
        self.expect("size")?;
        let (size_world, size_at) = self.number("camera size")?;
        self.expect("}")?;
        match CameraBasis::new(direction_world, up_world) {
            Ok(_) => {}
            Err(CameraError::ZeroDirection) => {
                return error(direction_at, ParseErrorKind::ZeroDirection);
            }
            Err(CameraError::UpParallel) => {
                return error(up_token.location, ParseErrorKind::UpParallel);
            }
        }
        if size_world <= 0.0 {
            return error(
                size_at,
                ParseErrorKind::NonPositiveSize { size: size_world },
            );
        }
        if size_world < MIN_VIEW_SIZE {
            return error(size_at, ParseErrorKind::SizeTooSmall { size: size_world });
        }
        Ok(OrthographicCamera {
            center_world,
            direction_world,
            up_world,
            size_world,
        })
    }

    fn background(&mut self) -> Result<Vec3, ParseError> {
        self.expect("{")?;
        self.expect("color")?;
        let colour = self.colour("background color")?;
        self.expect("}")?;
        Ok(colour)
    }

    fn materials(&mut self) -> Result<Vec<Material>, ParseError> {
        self.expect("{")?;
        self.expect("numMaterials")?;
        let (declared, declared_at) = self.count("numMaterials")?;
        let mut materials = Vec::new();
        loop {
            const EXPECTED: &str = "'PhongMaterial', 'Material' or '}'";
            let token = self.next(|| EXPECTED.to_owned())?;
            match token.text {
                "PhongMaterial" | "Material" => materials.push(self.material()?),
                "}" => break,
                _ => return Self::unexpected(token, EXPECTED),
            }
        }
        if materials.len() as u64 != declared {
            return error(
                declared_at,
                ParseErrorKind::CountMismatch {
                    block: "Materials",
                    items: "materials",
                    declared,
                    found: materials.len() as u64,
                },
            );
        }
        Ok(materials)
    }

    fn material(&mut self) -> Result<Material, ParseError> {
        const EXPECTED: &str = "'diffuseColor' or '}'";
        self.expect("{")?;
        let token = self.next(|| EXPECTED.to_owned())?;
        match token.text {
            "}" => Ok(Material::default()),
            "diffuseColor" => {
                let diffuse_colour = self.colour("diffuseColor")?;
                self.expect("}")?;
                Ok(Material { diffuse_colour })
            }
            _ => Self::unexpected(token, EXPECTED),
        }
    }

    /// A `Group` block after its keyword; `depth` is 1 for the top-level group.
    fn group(&mut self, depth: usize) -> Result<(), ParseError> {
        let open = self.expect("{")?;
        if depth > MAX_GROUP_DEPTH {
            return error(
                open.location,
                ParseErrorKind::TooDeep {
                    max: MAX_GROUP_DEPTH,
                },
            );
        }
        self.expect("numObjects")?;
        let (declared, declared_at) = self.count("numObjects")?;
        let mut found: u64 = 0;
        loop {
            const EXPECTED: &str = "'MaterialIndex', 'Sphere', 'Group' or '}'";
            let token = self.next(|| EXPECTED.to_owned())?;
            match token.text {
                "MaterialIndex" => {
                    let (index, location) = self.count("MaterialIndex")?;
                    self.material_references.push((index, location));
                    // Out-of-range indices are reported at the end, once the materials are known.
                    self.current_material = Some(u32::try_from(index).unwrap_or(u32::MAX));
                }
                "Sphere" => match self.take_run_at(&token) {
                    0 => {
                        self.sphere()?;
                        found += 1;
                    }
                    spheres => found += spheres,
                },
                "Group" => {
                    self.group(depth + 1)?;
                    found += 1;
                }
                "}" => break,
                _ => return Self::unexpected(token, EXPECTED),
            }
        }
        if found != declared {
            return error(
                declared_at,
                ParseErrorKind::CountMismatch {
                    block: "Group",
                    items: "objects",
                    declared,
                    found,
                },
            );
        }
        Ok(())
    }

    pub(super) fn sphere(&mut self) -> Result<(), ParseError> {
        self.expect("{")?;
        self.expect("center")?;
        let (center_world, _) = self.vector("sphere center")?;
        self.expect("radius")?;
        let (radius_world, radius_at) = self.number("sphere radius")?;
        self.expect("}")?;
        if radius_world < 0.0 {
            return error(
                radius_at,
                ParseErrorKind::NegativeRadius {
                    radius: radius_world,
                },
            );
        }
        self.spheres.push(Sphere {
            center_world,
            radius_world,
            material: self.current_material,
        });
        if self.spheres_from_byte.is_none() {
            self.spheres_from_byte = Some(self.lexer.bytes_consumed_and_left().0);
        }
        self.reserve_once_past_threshold(0, 0);
        if self.spheres.len().is_multiple_of(SPHERES_PER_REPORT) {
            (self.progress)(self.lexer.share_consumed());
        }
        Ok(())
    }

    /// [`Self::reserve_for_the_rest`], once: when the spheres listed and `coming_spheres` reach
    /// [`SPHERES_BEFORE_RESERVE`].
    pub(super) fn reserve_once_past_threshold(
        &mut self,
        coming_spheres: usize,
        coming_references: usize,
    ) {
        if !self.reserved && self.spheres.len() + coming_spheres >= SPHERES_BEFORE_RESERVE {
            self.reserve_for_the_rest(coming_spheres, coming_references);
        }
    }

    /// Room for `coming_spheres` and `coming_references` (a run about to be added, read up to where
    /// the lexer is) and for as many more spheres and `MaterialIndex` statements as the rest of
    /// the text holds at the density seen since the spheres began, a tenth more to spare, and
    /// never more than it could hold at all: a big file's lists then grow once instead of
    /// doubling twenty times, each time copying them into fresh memory and leaving the old block
    /// behind (slower, and a higher peak). Room not filled is address space only (its pages are
    /// never touched).
    fn reserve_for_the_rest(&mut self, coming_spheres: usize, coming_references: usize) {
        self.reserved = true;
        let (consumed, left) = self.lexer.bytes_consumed_and_left();
        let span = consumed - self.spheres_from_byte.unwrap_or(0).min(consumed);
        let more = |seen: usize, fewest_bytes: usize| {
            let per_byte = seen as f64 / span.max(1) as f64;
            ((left as f64 * per_byte * 1.1) as usize).min(left / fewest_bytes)
        };
        let spheres = self.spheres.len() + coming_spheres;
        let references = self.material_references.len() + coming_references;
        self.spheres
            .reserve(coming_spheres + more(spheres, MIN_SPHERE_BYTES));
        self.material_references
            .reserve(coming_references + more(references, MIN_MATERIAL_INDEX_BYTES));
    }
}
