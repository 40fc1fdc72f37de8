//! `linkage serve [DIR]`: the page (`web/`, its engine built by
//! `web/build.sh`) served to this machine's browser at
//! http://127.0.0.1:PORT/ — files only, read-only, on the loopback
//! interface: a browser will not run the page's WebAssembly and worker
//! from a folder opened as `file://` without flags, and the page needs no
//! network beyond this.

use crate::cli::ServeArgs;
use crate::failure::Failure;
use std::io::{BufRead, BufReader, Write};
use std::net::{Ipv4Addr, TcpListener, TcpStream};
use std::path::{Component, Path, PathBuf};

/// The longest request head read (a browser's is well under this).
const MOST_HEAD: usize = 16 * 1024;

pub fn run(args: &ServeArgs) -> Result<(), Failure> {
    let root = args.dir.clone();
    let engine = root.join("pkg").join("linkage_web_bg.wasm");
    if !root.join("index.html").is_file() || !engine.is_file() {
        return Err(Failure::Malformed(format!(
            "{} is not the page built: it needs index.html and pkg/linkage_web_bg.wasm \
             (build the engine with `bash web/build.sh`)",
            root.display()
        )));
    }
    let listener = TcpListener::bind((Ipv4Addr::LOCALHOST, args.port))
        .map_err(|e| Failure::Io(format!("cannot listen on 127.0.0.1:{}: {e}", args.port)))?;
    let port = listener
        .local_addr()
        .map_err(|e| Failure::Io(format!("the listening port: {e}")))?
        .port();
    eprintln!(
        "serving {} at http://127.0.0.1:{port}/ (Ctrl-C stops)",
        root.display()
    );
    for stream in listener.incoming() {
        let Ok(stream) = stream else { continue };
        let root = root.clone();
        // A slow or broken client holds up only its own connection.
        std::thread::spawn(move || {
            let _ = answer(&root, stream);
        });
    }
    Ok(())
}

/// Answers one request on `stream` with a file of `root`.
fn answer(root: &Path, mut stream: TcpStream) -> std::io::Result<()> {
    let mut reader = BufReader::new(stream.try_clone()?);
    let mut head = Vec::new();
    let mut line = String::new();
    loop {
        line.clear();
        if reader.read_line(&mut line)? == 0 || line == "\r\n" || line == "\n" {
            break;
        }
        head.push(line.clone());
        if head.iter().map(String::len).sum::<usize>() > MOST_HEAD {
            return respond(
                &mut stream,
                "431 Request Header Fields Too Large",
                "text/plain",
                b"",
            );
        }
    }
    let mut words = head
        .first()
        .map(|l| l.split_whitespace())
        .into_iter()
        .flatten();
    let (method, target) = (words.next().unwrap_or(""), words.next().unwrap_or(""));
    if method != "GET" && method != "HEAD" {
        return respond(
            &mut stream,
            "405 Method Not Allowed",
            "text/plain",
            b"GET only\n",
        );
    }
    let body_wanted = method == "GET";
    match file_of(root, target).and_then(|path| Some((std::fs::read(&path).ok()?, path))) {
        Some((bytes, path)) => {
            let body: &[u8] = if body_wanted { &bytes } else { b"" };
            respond_with_length(&mut stream, "200 OK", kind(&path), body, bytes.len())
        }
        None => respond(&mut stream, "404 Not Found", "text/plain", b"not found\n"),
    }
}

/// The file of `root` a request's target names (`/` is `index.html`):
/// none for a target that would leave `root`, is not a file, or is not
/// plain text after its percent-escapes are read.
fn file_of(root: &Path, target: &str) -> Option<PathBuf> {
    let path = target.split(['?', '#']).next()?;
    let path = percent_decoded(path.strip_prefix('/')?)?;
    let path = if path.is_empty() || path.ends_with('/') {
        format!("{path}index.html")
    } else {
        path
    };
    let relative = Path::new(&path);
    let plain = relative
        .components()
        .all(|c| matches!(c, Component::Normal(_)));
    if !plain || path.contains('\\') {
        return None;
    }
    let full = root.join(relative);
    full.is_file().then_some(full)
}

/// `%XX` escapes read as UTF-8; none if an escape or the result is bad.
fn percent_decoded(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut k = 0;
    while k < bytes.len() {
        if bytes[k] == b'%' {
            let hex = std::str::from_utf8(bytes.get(k + 1..k + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            k += 3;
        } else {
            out.push(bytes[k]);
            k += 1;
        }
    }
    String::from_utf8(out).ok()
}

/// The content type of a file of the page, by its extension.
fn kind(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()).unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" => "text/javascript; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "wasm" => "application/wasm",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "json" => "application/json",
        "toml" | "txt" | "md" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

fn respond(stream: &mut TcpStream, status: &str, kind: &str, body: &[u8]) -> std::io::Result<()> {
    respond_with_length(stream, status, kind, body, body.len())
}

fn respond_with_length(
    stream: &mut TcpStream,
    status: &str,
    kind: &str,
    body: &[u8],
    length: usize,
) -> std::io::Result<()> {
    write!(
        stream,
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {length}\r\n\
         Cache-Control: no-cache\r\nConnection: close\r\n\r\n"
    )?;
    stream.write_all(body)?;
    stream.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Only files under the root are served; a way out of it is none.
    #[test]
    fn only_files_of_the_root_are_served() {
        let root = std::env::temp_dir().join(format!("linkage-serve-{}", std::process::id()));
        std::fs::create_dir_all(root.join("pkg")).unwrap();
        std::fs::write(root.join("index.html"), "<html>").unwrap();
        std::fs::write(root.join("pkg/a b.js"), "x").unwrap();
        assert_eq!(file_of(&root, "/"), Some(root.join("index.html")));
        assert_eq!(
            file_of(&root, "/?selftest#x"),
            Some(root.join("index.html"))
        );
        assert_eq!(
            file_of(&root, "/pkg/a%20b.js"),
            Some(root.join("pkg/a b.js"))
        );
        for outside in [
            "/../etc/passwd",
            "/pkg/../../x",
            "/%2e%2e/x",
            "//etc/passwd",
            "/pkg",
            "x",
            "/%zz",
            "/a\\b",
        ] {
            assert_eq!(file_of(&root, outside), None, "{outside}");
        }
        std::fs::remove_dir_all(root).unwrap();
    }
}
