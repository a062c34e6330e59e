//! Geometry the renderer and its oracles share: the camera's orthonormal basis and pixel grid
//! ([`camera`]), and the careful general ray–sphere intersection ([`ray_sphere`]).

pub mod camera;
pub mod ray_sphere;
