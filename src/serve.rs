//! `rtcdoc serve`: build into memory, serve on 127.0.0.1, watch the profiles, the configuration
//! and the theme, rebuild incrementally and live-reload open browsers over a websocket.
//!
//! Errors in a changed profile are printed and sent to the browsers as an overlay; the last good
//! site stays served.

use crate::build::BuildOptions;
use crate::incremental::{UpdateError, Workspace};
use anyhow::{Context, Result};
use notify::{RecursiveMode, Watcher};
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::sync::{Arc, Mutex, RwLock};
use std::time::Duration;

/// Path of the live-reload script and websocket, outside the site's own namespace.
const RELOAD_JS: &str = "/__rtcdoc/livereload.js";
const RELOAD_WS: &str = "/__rtcdoc/ws";

/// The script injected into every served HTML page: reloads on `reload`, shows an overlay on
/// `error:<text>` (the text is set with textContent, never parsed as HTML).
const LIVERELOAD: &str = r#"(function () {
  "use strict";
  var overlay = null;
  function show(text) {
    if (!overlay) {
      overlay = document.createElement("pre");
      overlay.id = "rtcdoc-error-overlay";
      overlay.setAttribute("role", "alert");
      overlay.style.cssText = "position:fixed;inset:auto 0 0 0;max-height:50vh;overflow:auto;margin:0;padding:1em;" +
        "background:#3b0a0a;color:#ffd7d7;font:13px/1.4 monospace;z-index:2147483647;white-space:pre-wrap";
      document.body.appendChild(overlay);
    }
    overlay.textContent = text;
  }
  function connect() {
    var ws = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + "/__rtcdoc/ws");
    ws.onmessage = function (ev) {
      var m = String(ev.data);
      if (m === "reload") { location.reload(); }
      else if (m.indexOf("error:") === 0) { show(m.slice(6)); }
    };
    ws.onclose = function () { setTimeout(connect, 1000); };
  }
  connect();
})();
"#;

/// A finding as the command line prints it ([`Diagnostic::cli_text`]), its file named by
/// `file_name`.
///
/// [`Diagnostic::cli_text`]: crate::diagnostic::Diagnostic::cli_text
fn finding(
    d: &crate::diagnostic::Diagnostic,
    file_name: Option<&(dyn Fn(&str) -> String + Send + Sync)>,
) -> String {
    match file_name {
        Some(f) => d.cli_text(&f(&d.file)),
        None => d.cli_text(&d.file),
    }
}

/// Re-reads the build options (after the configuration file changed).
pub type Reconfigure = Arc<dyn Fn() -> Result<BuildOptions> + Send + Sync>;

/// Options of `rtcdoc serve`.
#[derive(Clone)]
pub struct ServeOptions {
    pub build: BuildOptions,
    /// Port on 127.0.0.1; 0 picks a free one.
    pub port: u16,
    /// Extra paths to watch (configuration file, theme directory): a change in one rebuilds
    /// the whole site, with the options `reconfigure` gives when there is one.
    pub watch: Vec<PathBuf>,
    pub reconfigure: Option<Reconfigure>,
    /// How a rebuild's findings name their files (the command line: as the user can open them,
    /// as its first build's findings do); `None`: as the catalogue has them.
    pub file_name: Option<FileName>,
}

/// Names a finding's file (catalogue path) for the user.
pub type FileName = Arc<dyn Fn(&str) -> String + Send + Sync>;

struct Shared {
    files: RwLock<Arc<BTreeMap<String, Vec<u8>>>>,
    error: RwLock<Option<String>>,
    clients: Mutex<Vec<mpsc::Sender<String>>>,
    stop: AtomicBool,
}

impl Shared {
    fn broadcast(&self, msg: &str) {
        let mut clients = self.clients.lock().unwrap_or_else(|e| e.into_inner());
        clients.retain(|c| c.send(msg.to_string()).is_ok());
    }
}

/// A running server (stops when dropped).
pub struct ServerHandle {
    port: u16,
    shared: Arc<Shared>,
    threads: Vec<std::thread::JoinHandle<()>>,
    /// What the first build found (the CLI prints it like `build` does).
    first_diagnostics: Vec<crate::diagnostic::Diagnostic>,
    /// The first build's notes on missing or cut history ([`crate::catalog::Catalog::history_notes`]).
    first_history_notes: Vec<String>,
}

impl ServerHandle {
    /// The diagnostics of the first build.
    pub fn first_diagnostics(&self) -> &[crate::diagnostic::Diagnostic] {
        &self.first_diagnostics
    }
    /// The first build's notes on history it could not read whole (a shallow clone, a
    /// repository git refuses), as `build` prints them.
    pub fn first_history_notes(&self) -> &[String] {
        &self.first_history_notes
    }
    /// The port the server listens on.
    pub fn port(&self) -> u16 {
        self.port
    }
    /// The address to open in a browser.
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port)
    }
    /// Blocks until the server stops.
    pub fn wait(mut self) {
        for t in self.threads.drain(..) {
            let _ = t.join();
        }
    }
    /// Stops the server.
    pub fn stop(mut self) {
        self.shutdown();
    }
    fn shutdown(&mut self) {
        self.shared.stop.store(true, Ordering::SeqCst);
        // Wake the accept loop.
        let _ = TcpStream::connect(("127.0.0.1", self.port));
        for t in self.threads.drain(..) {
            let _ = t.join();
        }
    }
}

impl Drop for ServerHandle {
    fn drop(&mut self) {
        if !self.threads.is_empty() {
            self.shutdown();
        }
    }
}

/// Builds the site, starts serving and watching; returns at once. `log` receives one line per
/// event (rebuilds, errors).
pub fn start(opts: ServeOptions, log: Arc<dyn Fn(&str) + Send + Sync>) -> Result<ServerHandle> {
    let mut ws = Workspace::open(&opts.build)?;
    let first_diagnostics = ws.catalog().diagnostics.clone();
    let first_history_notes = ws.catalog().history_notes.clone();
    let shared = Arc::new(Shared {
        files: RwLock::new(Arc::new(ws.files().clone())),
        error: RwLock::new(None),
        clients: Mutex::new(Vec::new()),
        stop: AtomicBool::new(false),
    });
    let listener = TcpListener::bind(("127.0.0.1", opts.port))
        .with_context(|| format!("cannot listen on 127.0.0.1:{}", opts.port))?;
    let port = listener.local_addr()?.port();

    // Watcher → channel of changed paths.
    let (tx, rx) = mpsc::channel::<notify::Result<notify::Event>>();
    let mut watcher = notify::recommended_watcher(tx).context("cannot watch files")?;
    watcher
        .watch(&opts.build.input, RecursiveMode::Recursive)
        .with_context(|| format!("cannot watch `{}`", opts.build.input.display()))?;
    for w in &opts.watch {
        if w.exists() {
            let _ = watcher.watch(w, RecursiveMode::Recursive);
        }
    }

    let mut threads = Vec::new();
    let s = shared.clone();
    threads.push(std::thread::spawn(move || {
        for stream in listener.incoming() {
            if s.stop.load(Ordering::SeqCst) {
                break;
            }
            if let Ok(stream) = stream {
                let s = s.clone();
                std::thread::spawn(move || {
                    let _ = handle(stream, &s);
                });
            }
        }
    }));

    let s = shared.clone();
    let output = crate::output::absolute(&opts.build.output).unwrap_or_default();
    let reconfigure = opts.reconfigure.clone();
    let file_name = opts.file_name.clone();
    let watch_extra: Vec<PathBuf> = opts.watch.clone();
    threads.push(std::thread::spawn(move || {
        let _watcher = watcher; // kept alive for the life of the loop
        while !s.stop.load(Ordering::SeqCst) {
            let first = match rx.recv_timeout(Duration::from_millis(200)) {
                Ok(ev) => ev,
                Err(mpsc::RecvTimeoutError::Timeout) => continue,
                Err(_) => break,
            };
            // Debounce: editors write a file in several steps.
            let mut paths: Vec<PathBuf> = Vec::new();
            let mut push = |ev: notify::Result<notify::Event>| {
                if let Ok(ev) = ev {
                    if matches!(ev.kind, notify::EventKind::Access(_)) {
                        return;
                    }
                    paths.extend(ev.paths);
                }
            };
            push(first);
            std::thread::sleep(Duration::from_millis(80));
            while let Ok(ev) = rx.try_recv() {
                push(ev);
            }
            paths.sort();
            paths.dedup();
            paths.retain(|p| !p.starts_with(&output));
            if paths.is_empty() {
                continue;
            }
            let start = std::time::Instant::now();
            let full = paths.iter().any(|p| {
                // IDL files define what every type page shows: reload everything.
                p.extension().is_some_and(|e| e.eq_ignore_ascii_case("idl"))
                    || watch_extra.iter().any(|w| p.starts_with(w))
            });
            let result = if full {
                let opts = match &reconfigure {
                    Some(f) => f(),
                    None => Ok(ws.options().clone()),
                };
                opts.and_then(|o| ws.reload(&o))
                    .map(|_| None)
                    .map_err(|e| UpdateError::Other(format!("{e:#}")))
            } else {
                ws.update(&paths).map(Some)
            };
            match result {
                Ok(Some(r)) if r.rendered == 0 => {}
                Ok(r) => {
                    *s.files.write().unwrap_or_else(|e| e.into_inner()) =
                        Arc::new(ws.files().clone());
                    *s.error.write().unwrap_or_else(|e| e.into_inner()) = None;
                    let n = r.map(|r| r.rendered).unwrap_or(ws.files().len());
                    log(&format!(
                        "rebuilt {n} file(s) in {:.0} ms",
                        start.elapsed().as_secs_f64() * 1000.0
                    ));
                    s.broadcast("reload");
                }
                Err(e) => {
                    let text = match e {
                        UpdateError::Profiles(d) => d
                            .iter()
                            .map(|d| finding(d, file_name.as_deref()))
                            .collect::<Vec<_>>()
                            .join("\n"),
                        UpdateError::Other(t) => t,
                    };
                    log(&format!(
                        "error (the last good site is still served):\n{text}"
                    ));
                    *s.error.write().unwrap_or_else(|e| e.into_inner()) = Some(text.clone());
                    s.broadcast(&format!("error:{text}"));
                }
            }
        }
    }));
    Ok(ServerHandle {
        port,
        shared,
        threads,
        first_diagnostics,
        first_history_notes,
    })
}

fn content_type(path: &str) -> &'static str {
    match Path::new(path)
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
    {
        "html" => "text/html; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "js" => "text/javascript; charset=utf-8",
        "json" => "application/json",
        "svg" => "image/svg+xml",
        "xml" => "application/xml",
        "png" => "image/png",
        "txt" | "md" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

fn percent_decode(s: &str) -> String {
    fn hex(b: u8) -> Option<u8> {
        (b as char).to_digit(16).map(|d| d as u8)
    }
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' && i + 2 < b.len() {
            if let (Some(h), Some(l)) = (hex(b[i + 1]), hex(b[i + 2])) {
                out.push(h * 16 + l);
                i += 3;
                continue;
            }
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

fn respond(stream: &mut TcpStream, status: &str, ctype: &str, body: &[u8]) -> std::io::Result<()> {
    write!(
        stream,
        "HTTP/1.1 {status}\r\nContent-Type: {ctype}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n",
        body.len()
    )?;
    stream.write_all(body)?;
    stream.flush()
}

fn inject_reload(html: &[u8]) -> Vec<u8> {
    let tag = format!("<script src=\"{RELOAD_JS}\"></script>");
    let text = String::from_utf8_lossy(html);
    match text.rfind("</body>") {
        Some(i) => format!("{}{tag}{}", &text[..i], &text[i..]).into_bytes(),
        None => format!("{text}{tag}").into_bytes(),
    }
}

fn handle(mut stream: TcpStream, shared: &Shared) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    let mut reader = BufReader::new(stream.try_clone()?);
    let mut request_line = String::new();
    reader.by_ref().take(8192).read_line(&mut request_line)?;
    let mut headers = BTreeMap::new();
    loop {
        let mut line = String::new();
        let n = reader.by_ref().take(8192).read_line(&mut line)?;
        if n == 0 || line == "\r\n" || line == "\n" || headers.len() > 100 {
            break;
        }
        if let Some((k, v)) = line.split_once(':') {
            headers.insert(k.trim().to_ascii_lowercase(), v.trim().to_string());
        }
    }
    let mut parts = request_line.split_whitespace();
    let (method, target) = (parts.next().unwrap_or(""), parts.next().unwrap_or("/"));
    if method != "GET" && method != "HEAD" {
        return respond(
            &mut stream,
            "405 Method Not Allowed",
            "text/plain",
            b"method not allowed\n",
        );
    }
    let path = percent_decode(target.split(['?', '#']).next().unwrap_or("/"));
    if path == RELOAD_WS {
        let Some(key) = headers.get("sec-websocket-key") else {
            return respond(
                &mut stream,
                "400 Bad Request",
                "text/plain",
                b"websocket key missing\n",
            );
        };
        let accept = tungstenite::handshake::derive_accept_key(key.as_bytes());
        write!(
            stream,
            "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: {accept}\r\n\r\n"
        )?;
        stream.set_read_timeout(None)?;
        stream.set_write_timeout(Some(Duration::from_secs(5)))?;
        let mut ws = tungstenite::WebSocket::from_raw_socket(
            stream,
            tungstenite::protocol::Role::Server,
            None,
        );
        let (tx, rx) = mpsc::channel::<String>();
        // A browser that connects while the site is broken sees the overlay at once.
        if let Some(e) = shared
            .error
            .read()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
        {
            let _ = tx.send(format!("error:{e}"));
        }
        shared
            .clients
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(tx);
        while !shared.stop.load(Ordering::SeqCst) {
            match rx.recv_timeout(Duration::from_secs(15)) {
                Ok(msg) => {
                    if ws.send(tungstenite::Message::text(msg)).is_err() {
                        break;
                    }
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {
                    if ws
                        .send(tungstenite::Message::Ping(Vec::new().into()))
                        .is_err()
                    {
                        break;
                    }
                }
                Err(_) => break,
            }
        }
        return Ok(());
    }
    if path == RELOAD_JS {
        return respond(
            &mut stream,
            "200 OK",
            content_type(".js"),
            LIVERELOAD.as_bytes(),
        );
    }
    let mut rel = path.trim_start_matches('/').to_string();
    if rel.is_empty() || rel.ends_with('/') {
        rel.push_str("index.html");
    }
    let files = shared
        .files
        .read()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    let (status, rel, body) = match files
        .get(&rel)
        .or_else(|| files.get(&format!("{rel}/index.html")))
    {
        Some(b) => ("200 OK", rel, b.clone()),
        None => (
            "404 Not Found",
            "404.html".to_string(),
            files
                .get("404.html")
                .cloned()
                .unwrap_or_else(|| b"not found\n".to_vec()),
        ),
    };
    let body = if rel.ends_with(".html") {
        inject_reload(&body)
    } else {
        body
    };
    if method == "HEAD" {
        return respond(&mut stream, status, content_type(&rel), &[]);
    }
    respond(&mut stream, status, content_type(&rel), &body)
}

/// Opens `url` in the desktop's browser, if there is one (errors are ignored).
pub fn open_browser(url: &str) {
    let cmd = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        "xdg-open"
    };
    let _ = std::process::Command::new(cmd)
        .arg(url)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
}
