//! The viewer in a browser page (`wasm32`): the page's seam ([`Page`]), which the coordinator
//! holds and calls (the seam's methods are listed in `app/seam.rs`): what a page does where the
//! desktop uses files. The page's script starts the viewer through `app/start/page.rs`.
//!
//! * Files come in as bytes: dropped on the page, chosen with the browser's file input, or
//!   fetched from the page's own site (`?scene=URL`, or a URL typed in the path field). They land
//!   in the [`Page`]'s inbox and the viewer takes them at its next frame.
//! * Exports and saved views leave as downloads.
//! * Settings and views are kept in the browser's storage by eframe.
//!
//! A page has no threads here: loads, comparisons and exports run on the page's thread, and the
//! render worker renders one frame per page frame (see `platform/worker.rs`).

mod page_files;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::actions::{Action, Write};
use super::asked::Asked;
use super::compare::{ImageKind, dropped_image_kind};
use super::dialogs::DialogKind;
use super::settings::ExportSettings;
use super::status::Status;
use super::writes::{Stager, Writes};
use crate::output::atomic::FilesInMemory;
use crate::platform::browser::{download, download_name, set_title};
pub(crate) use page_files::Page;
use page_files::Purpose;

impl Page {
    /// A page opens the scene its address names (`?scene=`), not the last one (that was a file
    /// the page has no access to any more); it has no command line. That scene is asked for
    /// before the viewer starts (`WebHandle::start`), which gives the viewer the page it comes to.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn first_scene(
        &self,
        _input: Option<PathBuf>,
        _last_scene: Option<&Path>,
    ) -> Option<PathBuf> {
        None
    }

    /// True while the scene the page's address names is on its way: until it comes (or fails),
    /// the page renders no frame of the embedded default scene, which would only pass by.
    pub(crate) fn first_scene_on_its_way(&self) -> bool {
        self.fetching_scene()
    }

    /// A page's files are downloads: there is no folder an export would have to create.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn missing_export_folder(
        &self,
        _write: &Write,
        _typed_folder: &str,
    ) -> Option<PathBuf> {
        None
    }

    /// A file dropped on the page: the page gives its name, and its bytes are read later (they
    /// come in through [`Self::poll`], the kind decided by their name and content then).
    pub(crate) fn dropped(
        &mut self,
        file: egui::DroppedFileHandle,
        _chosen: ImageKind,
    ) -> Option<Asked> {
        self.read_dropped(file);
        None
    }

    /// Names the page (and eframe's viewport) `title`.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn set_title(&self, ctx: &egui::Context, title: &str) {
        ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.to_owned()));
        set_title(title);
    }

    /// Takes in the files that came to the page since the last frame, as what the viewer is to
    /// do with them. The watches stop when the comparison is closed (by the user, or by another
    /// scene opened): `compare_closes` is the comparison's count of closes.
    pub(crate) fn poll(&mut self, _ctx: &egui::Context, compare_closes: u64) -> Vec<Asked> {
        self.stop_watching_at(compare_closes);
        let mut asked = Vec::new();
        for incoming in self.take() {
            let bytes: Arc<[u8]> = match incoming.bytes {
                Ok(bytes) => bytes.into(),
                Err(error) => {
                    let message = if error.starts_with(&incoming.name) {
                        error
                    } else {
                        format!("{}: {error}", incoming.name)
                    };
                    asked.push(match incoming.purpose {
                        Purpose::Open => Asked::SceneError(message),
                        _ => Asked::Say(Status::error(message)),
                    });
                    continue;
                }
            };
            let name = incoming.name;
            let compared_as = match incoming.purpose {
                Purpose::Open => None,
                Purpose::Compare(kind) => Some(kind),
                Purpose::ByName => dropped_image_kind(&name),
                // A watched image written again is compared again (its watch stops when the
                // comparison is closed or another scene opened: above).
                Purpose::Rewritten(kind) => Some(kind),
            };
            asked.push(match compared_as {
                Some(kind) => Asked::CompareBytes(name, kind, bytes),
                None => Asked::OpenBytes(name, bytes),
            });
        }
        asked
    }

    /// Opens the scene at `path`: in a page, the path field holds an address on the page's
    /// site, fetched.
    pub(crate) fn open_path(&mut self, path: &Path) -> Option<Asked> {
        self.fetch_scene(&path.to_string_lossy(), None);
        None
    }

    /// The browser's file chooser to open a scene or an image; export and save download at once
    /// (the browser asks where, or saves to its downloads folder).
    pub(crate) fn open_dialog(
        &mut self,
        kind: DialogKind,
        _writes: &mut Writes,
        export: &ExportSettings,
        _ctx: &egui::Context,
    ) -> Option<Asked> {
        let chosen = match kind {
            DialogKind::Open => self.pick(Purpose::Open, ".txt,text/plain"),
            // Where the browser can, the image picked is watched, as the desktop watches it.
            DialogKind::CompareImage(kind) if self.pick_watched(kind) => Ok(()),
            DialogKind::CompareImage(kind) => {
                self.pick(Purpose::Compare(kind), ".png,.tga,image/png")
            }
            DialogKind::Export => {
                let base = PathBuf::from(export.path.trim());
                return Some(Asked::Apply(Action::Write(Write::ExportTo(base))));
            }
            DialogKind::SaveScene => {
                let path = PathBuf::from(export.scene_path.trim());
                return Some(Asked::Apply(Action::Write(Write::SaveViewTo(path))));
            }
        };
        chosen
            .err()
            .map(|error| Asked::Say(Status::error(format!("cannot choose a file: {error}"))))
    }

    /// The page's way to write the files `stage` stages: each downloaded now, named by its last
    /// part (the desktop writes them: `app::desktop`); what the status bar says: `done` (what was
    /// written: "exported", or the course files' range and size) and their names.
    #[expect(
        clippy::unused_self,
        reason = "a method, as each seam's are: the caller names no seam"
    )]
    pub(crate) fn write_files(
        &mut self,
        _writes: &mut Writes,
        _ctx: &egui::Context,
        (_running, done): (&str, String),
        stage: Stager,
    ) -> Status {
        let mut memory = FilesInMemory::default();
        let outcome = stage(&mut memory).and_then(|()| {
            let mut names = Vec::new();
            for (path, bytes) in &memory.files {
                let name = download_name(path);
                download(&name, bytes)?;
                names.push(name);
            }
            Ok(format!("{done} {} (downloaded)", names.join(", ")))
        });
        match outcome {
            Ok(message) => Status::info(message),
            Err(error) => Status::error(format!("download failed: {error}")),
        }
    }
}
