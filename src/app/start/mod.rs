//! How the viewer is started: in a window on the desktop ([`window`]: eframe's native options,
//! the renderer, or why no window can be opened), or in a browser page by the page's script
//! (`page`: the `WebHandle`). Each gives the coordinator the seam of its platform
//! (`app/seam.rs`).

#[cfg(target_arch = "wasm32")]
pub mod page;
#[cfg(not(target_arch = "wasm32"))]
pub mod window;
