//! The browser as a platform (`wasm32`): the page's window and address, fetching from the page's
//! own site, downloads, the page's title, and JavaScript's errors as text. What the viewer makes
//! of them is in `app::web`.

use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

/// The page's window, or why there is none.
pub fn window() -> Result<web_sys::Window, String> {
    web_sys::window().ok_or_else(|| "not in a browser window".to_owned())
}

/// What a JavaScript error says, as text.
pub fn js_error(value: &JsValue) -> String {
    value
        .dyn_ref::<js_sys::Error>()
        .map(|error| String::from(error.message()))
        .or_else(|| value.as_string())
        .unwrap_or_else(|| format!("{value:?}"))
}

/// `address` resolved against the page's address, when it is on the page's own site.
pub fn same_site_url(address: &str) -> Result<String, String> {
    let location = window()?.location();
    let page = location.href().map_err(|e| js_error(&e))?;
    let origin = location.origin().map_err(|e| js_error(&e))?;
    let url = web_sys::Url::new_with_base(address, &page)
        .map_err(|_| format!("{address}: not an address"))?;
    if url.origin() != origin {
        return Err(format!(
            "{address}: only scenes on this page's own site ({origin}) can be opened by address; \
             download the file and drop it on the page instead"
        ));
    }
    Ok(url.href())
}

/// The bytes at `url`, or why not (an HTTP status, a network error).
pub async fn fetch_bytes(url: &str) -> Result<Vec<u8>, String> {
    answer_bytes(url, window()?.fetch_with_str(url)).await
}

/// The bytes of `answer`, the browser's `fetch` of `url` (made here, or by the page's script), or
/// why not (an HTTP status, a network error).
pub async fn answer_bytes(url: &str, answer: js_sys::Promise) -> Result<Vec<u8>, String> {
    let response: web_sys::Response = JsFuture::from(answer)
        .await
        .map_err(|error| format!("cannot fetch {url}: {}", js_error(&error)))?
        .dyn_into()
        .map_err(|_| format!("cannot fetch {url}"))?;
    if !response.ok() {
        return Err(format!(
            "{url}: the server answered {} {}",
            response.status(),
            response.status_text()
        ));
    }
    let buffer = JsFuture::from(response.array_buffer().map_err(|e| js_error(&e))?)
        .await
        .map_err(|e| js_error(&e))?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}

/// Offers `bytes` as a download named `name`.
pub fn download(name: &str, bytes: &[u8]) -> Result<(), String> {
    let document = window()?.document().ok_or("the page has no document")?;
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("application/octet-stream");
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
        .map_err(|e| js_error(&e))?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(|e| js_error(&e))?;
    let anchor: web_sys::HtmlAnchorElement = document
        .create_element("a")
        .map_err(|e| js_error(&e))?
        .dyn_into()
        .map_err(|_| "cannot make a link")?;
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.click();
    // The download has its bytes once it started; the address is released a minute later.
    let release = Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&url);
    });
    let _ = window()?
        .set_timeout_with_callback_and_timeout_and_arguments_0(release.unchecked_ref(), 60_000);
    Ok(())
}

/// The page address's `scene` parameter (`?scene=scenes/scene1_02.txt`), if any.
pub fn scene_parameter() -> Option<String> {
    let search = window().ok()?.location().search().ok()?;
    web_sys::UrlSearchParams::new_with_str(&search)
        .ok()?
        .get("scene")
        .filter(|scene| !scene.trim().is_empty())
}

/// Sets the page's title.
pub fn set_title(title: &str) {
    if let Some(document) = window().ok().and_then(|w| w.document()) {
        document.set_title(title);
    }
}

/// The name a browser page downloads `path` as: its last part (the viewer's downloads).
#[cfg(feature = "gui")]
pub(crate) fn download_name(path: &std::path::Path) -> String {
    path.file_name().map_or_else(
        || "raytracer".to_owned(),
        |name| name.to_string_lossy().into_owned(),
    )
}

/// The browser's file picker with lasting access to the file chosen (`showOpenFilePicker`, the
/// File System Access API: Chromium), where it has one.
pub fn file_picker() -> Option<js_sys::Function> {
    let window = web_sys::window()?;
    js_sys::Reflect::get(&window, &"showOpenFilePicker".into())
        .ok()?
        .dyn_into()
        .ok()
}

/// Shows `picker` for one TGA or PNG image: the handle of the file chosen, `None` when the user
/// cancelled.
pub async fn pick_handle(picker: &js_sys::Function) -> Result<Option<JsValue>, String> {
    let accept = js_sys::Object::new();
    let extensions = js_sys::Array::of2(&".png".into(), &".tga".into());
    js_sys::Reflect::set(&accept, &"image/*".into(), &extensions).map_err(|e| js_error(&e))?;
    let kind = js_sys::Object::new();
    js_sys::Reflect::set(&kind, &"description".into(), &"TGA or PNG image".into())
        .and_then(|_| js_sys::Reflect::set(&kind, &"accept".into(), &accept))
        .map_err(|e| js_error(&e))?;
    let options = js_sys::Object::new();
    js_sys::Reflect::set(&options, &"types".into(), &js_sys::Array::of1(&kind))
        .map_err(|e| js_error(&e))?;
    let window = window()?;
    let promise: js_sys::Promise = picker
        .call1(&window, &options)
        .map_err(|e| js_error(&e))?
        .dyn_into()
        .map_err(|_| "the file picker gave no promise".to_owned())?;
    match JsFuture::from(promise).await {
        Ok(handles) => Ok(js_sys::Array::from(&handles).get(0).dyn_into().ok()),
        // The user closed the picker.
        Err(error)
            if js_sys::Reflect::get(&error, &"name".into()).ok() == Some("AbortError".into()) =>
        {
            Ok(None)
        }
        Err(error) => Err(js_error(&error)),
    }
}

/// The file a picked `handle` stands for, as it is now.
pub async fn file_of(handle: &JsValue) -> Result<web_sys::File, String> {
    let get_file: js_sys::Function = js_sys::Reflect::get(handle, &"getFile".into())
        .map_err(|e| js_error(&e))?
        .dyn_into()
        .map_err(|_| "not a file handle".to_owned())?;
    let promise: js_sys::Promise = get_file
        .call0(handle)
        .map_err(|e| js_error(&e))?
        .dyn_into()
        .map_err(|_| "not a file handle".to_owned())?;
    JsFuture::from(promise)
        .await
        .map_err(|e| js_error(&e))?
        .dyn_into()
        .map_err(|_| "not a file".to_owned())
}

/// Waits `ms` milliseconds without holding the page's thread.
pub async fn sleep_ms(ms: i32) {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        if let Ok(window) = window() {
            let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, ms);
        }
    });
    let _ = JsFuture::from(promise).await;
}
