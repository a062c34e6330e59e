//! The page's files on their way in (`wasm32`): dropped on the page, chosen with the browser's
//! file input or (where the browser has one) its file picker, which also watches the image
//! chosen, and fetched from the page's own site. They land in the [`Page`]'s inbox and the viewer
//! takes them at its next frame (`Page::poll`, in `app/web.rs`).

use std::cell::{Cell, RefCell};
use std::path::Path;
use std::rc::Rc;

use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

use crate::app::compare::ImageKind;
use crate::platform::browser::{
    answer_bytes, fetch_bytes, file_of, file_picker, js_error, pick_handle, same_site_url,
    sleep_ms, window,
};

/// How often a watched image is looked at, milliseconds.
pub(crate) const WATCH_INTERVAL_MS: i32 = 500;

/// What a file that came in is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Purpose {
    /// A scene to open.
    Open,
    /// An image to compare, as this kind.
    Compare(ImageKind),
    /// Decided by its name: an image (`.png`, `.tga`) is compared, anything else opened.
    ByName,
    /// A watched image, written again: compared again, as this kind, while it is on screen.
    Rewritten(ImageKind),
}

/// A file that came in, or why it could not.
#[derive(Debug)]
pub(crate) struct Incoming {
    pub(crate) name: String,
    pub(crate) purpose: Purpose,
    pub(crate) bytes: Result<Vec<u8>, String>,
}

/// A watched image's name, and the flag that stops its watch.
type Watch = (String, Rc<Cell<bool>>);

/// The page's side of the viewer: files on their way in, and the images it watches.
#[derive(Debug, Clone, Default)]
pub(crate) struct Page {
    inbox: Rc<RefCell<Vec<Incoming>>>,
    /// The images picked and watched, by name, each with the flag that stops its watch.
    watches: Rc<RefCell<Vec<Watch>>>,
    /// The comparison's count of closes when the watches were last looked at.
    closes_seen: Rc<Cell<u64>>,
    /// Scenes asked of the page's site whose answer has not come yet.
    scenes_fetching: Rc<Cell<u32>>,
    /// The viewer, woken when a file comes; none before it starts (the scene the page's address
    /// names is asked for before: `WebHandle::start`).
    viewer: Rc<RefCell<Option<egui::Context>>>,
}

impl Page {
    /// From now on, a file that comes wakes the viewer of `ctx`.
    pub(crate) fn attach(&self, ctx: &egui::Context) {
        *self.viewer.borrow_mut() = Some(ctx.clone());
    }

    fn deliver(&self, incoming: Incoming) {
        self.inbox.borrow_mut().push(incoming);
        if let Some(ctx) = self.viewer.borrow().as_ref() {
            ctx.request_repaint();
        }
    }

    /// Reads a file dropped on the page.
    pub(crate) fn read_dropped(&self, file: egui::DroppedFileHandle) {
        let page = self.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let name = file_name(file.path());
            let bytes = file.bytes_async().await;
            page.deliver(Incoming {
                name,
                purpose: Purpose::ByName,
                bytes,
            });
        });
    }

    /// Shows the browser's file chooser (files of `accept`, e.g. `.txt`) and reads the file
    /// chosen. Nothing comes in when the user cancels.
    pub(crate) fn pick(&self, purpose: Purpose, accept: &str) -> Result<(), String> {
        let document = window()?.document().ok_or("the page has no document")?;
        let input: web_sys::HtmlInputElement = document
            .create_element("input")
            .map_err(|e| js_error(&e))?
            .dyn_into()
            .map_err(|_| "cannot make a file input")?;
        input.set_type("file");
        input.set_accept(accept);
        let (page, chooser) = (self.clone(), input.clone());
        let on_change = Closure::once_into_js(move || {
            let Some(file) = chooser.files().and_then(|files| files.get(0)) else {
                return;
            };
            wasm_bindgen_futures::spawn_local(async move {
                let bytes = JsFuture::from(file.array_buffer())
                    .await
                    .map(|buffer| js_sys::Uint8Array::new(&buffer).to_vec())
                    .map_err(|e| js_error(&e));
                page.deliver(Incoming {
                    name: file.name(),
                    purpose,
                    bytes,
                });
            });
        });
        input.set_onchange(Some(on_change.unchecked_ref()));
        input.click();
        Ok(())
    }

    /// Fetches the scene at `address`, relative to the page. Only the page's own site is asked
    /// (a course page links its scenes); anything else is refused with a message. `asked` is
    /// that fetch when the page's script made it already (`WebHandle::start`).
    pub(crate) fn fetch_scene(&self, address: &str, asked: Option<js_sys::Promise>) {
        let name = address.rsplit('/').next().unwrap_or(address).to_owned();
        let url = match same_site_url(address) {
            Ok(url) => url,
            Err(error) => {
                self.deliver(Incoming {
                    name,
                    purpose: Purpose::Open,
                    bytes: Err(error),
                });
                return;
            }
        };
        let page = self.clone();
        self.scenes_fetching.set(self.scenes_fetching.get() + 1);
        wasm_bindgen_futures::spawn_local(async move {
            let bytes = match asked {
                Some(answer) => answer_bytes(&url, answer).await,
                None => fetch_bytes(&url).await,
            };
            page.scenes_fetching.set(page.scenes_fetching.get() - 1);
            page.deliver(Incoming {
                name,
                purpose: Purpose::Open,
                bytes,
            });
        });
    }

    /// Waits until no scene is on its way, or `most_ms` milliseconds have passed.
    pub(crate) async fn scenes_in(&self, most_ms: i32) {
        let mut waited_ms = 0;
        while self.fetching_scene() && waited_ms < most_ms {
            sleep_ms(5).await;
            waited_ms += 5;
        }
    }

    /// In a browser that has a file picker with lasting access to the file chosen (Chromium's
    /// File System Access API), shows it and compares the image chosen as `kind`; then watches
    /// it: looked at every [`WATCH_INTERVAL_MS`], read again once it has changed and its time and
    /// size have held for one look, and compared again. `false` where the browser has no such
    /// picker (the file input serves, with no watch).
    pub(crate) fn pick_watched(&self, kind: ImageKind) -> bool {
        let Some(picker) = file_picker() else {
            return false;
        };
        let page = self.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let handle = match pick_handle(&picker).await {
                Ok(Some(handle)) => handle,
                Ok(None) => return,
                Err(error) => {
                    let (name, purpose) = ("image".to_owned(), Purpose::Compare(kind));
                    page.deliver(Incoming {
                        name,
                        purpose,
                        bytes: Err(error),
                    });
                    return;
                }
            };
            let name = js_sys::Reflect::get(&handle, &"name".into())
                .ok()
                .and_then(|name| name.as_string())
                .unwrap_or_else(|| "image".to_owned());
            let stop = page.watch(&name);
            // The time and size delivered, and those seen at the last look.
            let (mut delivered, mut seen) = (None, None);
            while !stop.get() {
                if let Ok(file) = file_of(&handle).await {
                    let stamp = (file.last_modified(), file.size());
                    if delivered != Some(stamp) && (delivered.is_none() || seen == Some(stamp)) {
                        let purpose = match delivered {
                            None => Purpose::Compare(kind),
                            Some(_) => Purpose::Rewritten(kind),
                        };
                        let bytes = JsFuture::from(file.array_buffer())
                            .await
                            .map(|buffer| js_sys::Uint8Array::new(&buffer).to_vec())
                            .map_err(|e| js_error(&e));
                        let name = name.clone();
                        page.deliver(Incoming {
                            name,
                            purpose,
                            bytes,
                        });
                        delivered = Some(stamp);
                    }
                    seen = Some(stamp);
                } else {
                    // Gone, or being written: looked at again.
                    seen = None;
                }
                sleep_ms(WATCH_INTERVAL_MS).await;
            }
        });
        true
    }

    /// Starts a watch of the image `name` (an older one of the same name stops): the flag that
    /// stops it.
    fn watch(&self, name: &str) -> Rc<Cell<bool>> {
        self.stop_watching(name);
        let stop = Rc::new(Cell::new(false));
        let watch = (name.to_owned(), Rc::clone(&stop));
        self.watches.borrow_mut().push(watch);
        stop
    }

    /// Stops every watch when the comparison's count of closes (`closes`) has moved since the
    /// last look: the images watched were closed, or another scene opened.
    pub(crate) fn stop_watching_at(&self, closes: u64) {
        if self.closes_seen.replace(closes) != closes {
            for (_, stop) in self.watches.borrow_mut().drain(..) {
                stop.set(true);
            }
        }
    }

    /// Stops watching the image `name` (picked again).
    fn stop_watching(&self, name: &str) {
        self.watches.borrow_mut().retain(|(watched, stop)| {
            let same = watched == name;
            if same {
                stop.set(true);
            }
            !same
        });
    }

    /// Nothing came in since the last frame's look.
    /// True while a scene asked of the page's site has not come (its bytes or its error).
    pub(crate) fn fetching_scene(&self) -> bool {
        self.scenes_fetching.get() > 0
    }

    pub(crate) fn inbox_empty(&self) -> bool {
        self.inbox.borrow().is_empty()
    }

    pub(crate) fn take(&self) -> Vec<Incoming> {
        std::mem::take(&mut *self.inbox.borrow_mut())
    }
}

/// The last part of a dropped file's path (the page gives only the name).
fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}
