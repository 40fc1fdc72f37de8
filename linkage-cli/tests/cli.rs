//! The command-line tool as a script sees it: every file of the library
//! checks, analyses, sweeps and draws; the numbers it prints are the
//! library's to the bit (CSV round-trips every f64); mistakes give their
//! exit status and a located message; standard input works.

use linkage::file::MechanismFile;
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn tool() -> Command {
    Command::new(env!("CARGO_BIN_EXE_linkage"))
}

fn library() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 13, "the library of mechanisms");
    files
}

fn run(args: &[&str]) -> Output {
    tool().args(args).output().unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).unwrap()
}

#[test]
fn every_file_of_the_library_checks_analyses_sweeps_and_draws() {
    for file in library() {
        let path = file.to_str().unwrap();
        for args in [
            vec!["check", path],
            vec!["analyze", path, "-f", "json"],
            vec!["sweep", path, "--steps", "24", "-f", "csv"],
            vec!["draw", path],
            vec!["expand", path],
        ] {
            let out = run(&args);
            assert!(
                out.status.success(),
                "linkage {args:?}: {}\n{}",
                out.status,
                text(&out.stderr)
            );
            assert!(!out.stdout.is_empty(), "linkage {args:?} printed nothing");
        }
    }
}

/// The worksheet's four-bar swept by the tool, read back from CSV, is the
/// compiled four-bar's sweep from the same assembly, every number to the bit.
#[test]
fn the_sweep_in_csv_is_the_compiled_sweep_to_the_bit() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms/four_bar.toml");
    let out = run(&[
        "sweep",
        path.to_str().unwrap(),
        "--steps",
        "90",
        "-f",
        "csv",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let csv = text(&out.stdout);
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let file = MechanismFile::read(&path).unwrap();
    let driver = file.driver("theta2").unwrap();
    let bar = FourBar::WORKSHEET;
    let start = bar
        .assemble(
            &vector![driver.at.value],
            &file
                .assembly
                .as_ref()
                .unwrap()
                .pick::<2>(&["theta3", "theta4"])
                .unwrap(),
        )
        .unwrap();
    let options = SweepOptions {
        speed: driver.rate.value,
        ..SweepOptions::default()
    };
    let back = bar
        .sweep(
            &start.u,
            &Drive::Line {
                from: vector![driver.at.value],
                to: vector![driver.from.value],
                steps: 100,
            },
            &options,
        )
        .unwrap();
    let sweep = bar
        .sweep(
            &back.poses.last().unwrap().u,
            &Drive::Line {
                from: vector![driver.from.value],
                to: vector![driver.to.value],
                steps: 90,
            },
            &options,
        )
        .unwrap();
    assert_eq!(rows.len(), sweep.poses.len());
    for (row, pose) in rows.iter().zip(&sweep.poses) {
        let expected = [
            pose.v[0],
            pose.u[0],
            pose.u[1],
            pose.udot[0],
            pose.udot[1],
            pose.uddot[0],
            pose.uddot[1],
        ];
        for (x, y) in row.iter().zip(expected) {
            assert_eq!(x.to_bits(), y.to_bits(), "row {row:?}");
        }
    }
}

#[test]
fn mistakes_give_status_1_and_every_mistake_located() {
    let mut child = tool()
        .args(["check", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let file = "name = \"Crank\"\nequations = '''\nu = [x], v = [t],\nclosure = [x - l * t.sinn() - thta],\n'''\n[parameters]\nl = 2\n[drive.t]\nfrom = 0\nto = 1\n";
    child
        .stdin
        .take()
        .unwrap()
        .write_all(file.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let errors = text(&out.stderr);
    assert!(errors.contains("<stdin>:4:22"), "{errors}");
    assert!(errors.contains("unsupported function `sinn`"), "{errors}");
    assert!(errors.contains("unknown name `thta`"), "{errors}");
    assert!(out.stdout.is_empty());
}

#[test]
fn exit_statuses_say_what_failed() {
    assert_eq!(run(&["check", "/no/such/file.toml"]).status.code(), Some(4));
    assert_eq!(run(&["analyze"]).status.code(), Some(2));
    assert_eq!(run(&["frobnicate", "x"]).status.code(), Some(2));
    // A mechanism that does not assemble at its `at`: the analysis fails,
    // and says where in the file.
    let dir = std::env::temp_dir().join(format!("linkage-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("apart.toml");
    std::fs::write(
        &path,
        "name = \"Apart\"\nequations = '''\nu = [theta3, theta4],\nv = [theta2],\nclosure = [\n    l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,\n    l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),\n],\n'''\n[parameters]\nl1 = 100\nl2 = 1\nl3 = 1\nl4 = 1\n[drive.theta2]\nfrom = 0\nto = 1\n",
    )
    .unwrap();
    let out = run(&["analyze", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    let said = text(&out.stderr);
    assert!(
        said.starts_with(
            "error: the mechanism does not assemble at the drivers' `at` (theta2 = 0)"
        ),
        "{said}"
    );
    // Located at the drive's `from` (its `at`, not written).
    assert!(said.contains("apart.toml:16:8"), "{said}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn expand_writes_the_attribute_with_the_files_values() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms/four_bar.toml");
    let out = run(&["expand", path.to_str().unwrap()]);
    let rust = text(&out.stdout);
    assert!(rust.contains("#[linkage::linkage("), "{rust}");
    assert!(rust.contains("pub struct FourBar {"), "{rust}");
    // Each value reads back to the file's f64.
    let file = MechanismFile::read(&path).unwrap();
    for p in &file.parameters {
        let line = format!("{}: {:?},", p.name.text, p.quantity.value);
        assert!(rust.contains(&line), "{line} in {rust}");
    }
}

