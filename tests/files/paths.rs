//! A mechanism file cannot make the library read or write anything: every
//! string it holds — its title, its units, its values, keys and tables it
//! does not know — is text, never a path. Files whose every string is a
//! path, to a named pipe that would block whoever opened it and to files
//! that must stay as they are, are read, made into their mechanisms,
//! analysed, swept and drawn; nothing opens the pipe, nothing in the
//! folder changes.

use linkage::assembly::{Assemble, Pick};
use linkage::file::MechanismFile;
use linkage::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

/// A folder of its own, with a file that must not change and, where the
/// system has `mkfifo`, a named pipe that blocks whoever opens it.
struct Folder {
    path: PathBuf,
}

impl Folder {
    fn new(name: &str) -> Folder {
        let path = std::env::temp_dir().join(format!("linkage-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(path.join("work")).unwrap();
        std::fs::write(path.join("kept.txt"), "as it was\n").unwrap();
        // Without mkfifo, a plain file stands in for the pipe.
        let pipe = path.join("pipe");
        let made = std::process::Command::new("mkfifo").arg(&pipe).status();
        if !made.is_ok_and(|s| s.success()) {
            std::fs::write(&pipe, "a pipe\n").unwrap();
        }
        Folder { path }
    }

    /// Every file in the folder, with its contents (the pipe's never read).
    fn listing(&self) -> Vec<(String, Option<String>)> {
        fn walk(dir: &Path, root: &Path, out: &mut Vec<(String, Option<String>)>) {
            for entry in std::fs::read_dir(dir).unwrap() {
                let entry = entry.unwrap();
                let path = entry.path();
                let kind = entry.file_type().unwrap();
                let name = path.strip_prefix(root).unwrap().display().to_string();
                if kind.is_dir() {
                    walk(&path, root, out);
                } else if kind.is_file() {
                    out.push((name, Some(std::fs::read_to_string(&path).unwrap())));
                } else {
                    out.push((name, None));
                }
            }
        }
        let mut out = Vec::new();
        walk(&self.path, &self.path, &mut out);
        out.sort();
        out
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.path);
    }
}

/// The worksheet's four-bar, its every string a path into `folder`.
fn file_of_paths(folder: &Path) -> String {
    let pipe = folder.join("pipe").display().to_string();
    let kept = folder.join("kept.txt").display().to_string();
    include_str!("../../mechanisms/four_bar.toml")
        .replace(
            "title = \"The four-bar of the Maple worksheet\"",
            &format!("title = \"{pipe}\""),
        )
        .replace("[drawing]", &format!("[drawing]\n# {kept}"))
}

/// The file read and run through everything a user runs, on a thread of
/// its own: `None` if it did not end within a minute (it opened the pipe).
fn run_within_a_minute(text: String) -> Option<Result<String, String>> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(run(&text));
    });
    receive.recv_timeout(Duration::from_secs(60)).ok()
}

fn run(text: &str) -> Result<String, String> {
    let file = MechanismFile::parse(text).map_err(|e| e.to_string())?;
    let model = file.mechanism().map_err(|e| e.to_string())?;
    let model = model.fixed::<2, 1>().map_err(|e| e.to_string())?;
    let d = file.driver("theta2").unwrap();
    let at = vector![d.at.value];
    let pick = file
        .assembly
        .as_ref()
        .unwrap()
        .pick::<2>(&["theta3", "theta4"]);
    let mode = model
        .assemble(&at, &pick.unwrap_or(Pick::Index(0)))
        .map_err(|e| e.to_string())?;
    let pose = model
        .analyze(
            &mode.u,
            &at,
            &vector![d.rate.value],
            &vector![0.0],
            &Options::default(),
        )
        .map_err(|e| e.to_string())?;
    let drive = Drive::Line {
        from: vector![d.from.value],
        to: vector![d.to.value],
        steps: 36,
    };
    let sweep = model
        .sweep(&mode.u, &drive, &SweepOptions::default())
        .map_err(|e| e.to_string())?;
    #[cfg(feature = "draw")]
    {
        use linkage::draw::scene::Frame;
        let cycle: Vec<Frame> = (sweep.poses.iter())
            .map(|p| Frame::from_sweep_pose(&model, p))
            .collect();
        file.scene()
            .render(&Frame::from_analysis(&model, &pose), &cycle)
            .map_err(|e| e.to_string())
    }
    #[cfg(not(feature = "draw"))]
    Ok(format!("{:?} {}", pose.u, sweep.poses.len()))
}

#[test]
fn a_file_of_paths_opens_none_of_them() {
    let folder = Folder::new("file-paths");
    let before = folder.listing();
    let text = file_of_paths(&folder.path);
    let drawn = run_within_a_minute(text.clone())
        .expect("it ended: nothing opened the pipe")
        .unwrap();
    // The title is text: written into the picture, escaped, as it is.
    #[cfg(feature = "draw")]
    assert!(drawn.contains(&folder.path.join("pipe").display().to_string()));
    let _ = drawn;
    // Paths in the places the format has no path: unknown keys and tables,
    // units, values, names, the equations. Each is a mistake, located.
    let pipe = folder.path.join("pipe").display().to_string();
    let wrong = [
        format!("include = \"{pipe}\"\n{text}"),
        text.replace(
            "[drawing]",
            &format!("[include]\npath = \"{pipe}\"\n[drawing]"),
        ),
        text.replace("[drawing]", &format!("[drawing]\noutput = \"{pipe}\"")),
        text.replace("length_unit = \"mm\"", &format!("length_unit = \"{pipe}\"")),
        text.replace("l1 = \"80 mm\"", &format!("l1 = \"{pipe}\"")),
        text.replace("name = \"FourBar\"", &format!("name = \"{pipe}\"")),
        text.replace("trace = [\"G3\"]", &format!("trace = [\"{pipe}\"]")),
        text.replace(
            "u = [theta3",
            &format!("u = [include_str!(\"{pipe}\"), theta3"),
        ),
        text.replace("u = [theta3", "u = [include!(\"/etc/passwd\"), theta3"),
    ];
    for text in wrong {
        let result = run_within_a_minute(text.clone()).expect("it ended: nothing opened the pipe");
        assert!(result.is_err(), "{text}");
    }
    // Read from disk: the file, and nothing else.
    let path = folder.path.join("work/four_bar.toml");
    std::fs::write(&path, file_of_paths(&folder.path)).unwrap();
    assert!(MechanismFile::read(&path).is_ok());
    let mut expected = before;
    expected.push((
        "work/four_bar.toml".into(),
        Some(file_of_paths(&folder.path)),
    ));
    expected.sort();
    assert_eq!(folder.listing(), expected);
}
