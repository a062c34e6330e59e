//! The seam between the viewer and where it runs: the coordinator holds one [`Seam`] — the
//! desktop's ([`super::desktop::Desktop`]: files by path, the system's dialogs, writes into the
//! file system) or a browser page's ([`super::web::Page`]: files as bytes, the browser's file
//! chooser, downloads) — and calls it through the same methods on both (`first_scene`,
//! `first_scene_on_its_way`, `missing_export_folder`, `dropped`, `set_title`, `poll`,
//! `open_path`, `open_dialog`, `write_files`). They are given what they need to open, write,
//! watch and download, and never the coordinator: what a seam wants of the viewer comes back as
//! an [`Asked`](super::asked::Asked), which the coordinator carries out.

/// The seam of the platform the viewer is built for.
#[cfg(not(target_arch = "wasm32"))]
pub(crate) type Seam = super::desktop::Desktop;

/// The seam of the platform the viewer is built for.
#[cfg(target_arch = "wasm32")]
pub(crate) type Seam = super::web::Page;
