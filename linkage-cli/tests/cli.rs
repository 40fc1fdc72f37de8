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

/// The TOML files of `folder` (under the repository), at least `least`.
fn toml_files(folder: &str, least: usize) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(folder);
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= least, "the files of {folder}");
    files
}

fn library() -> Vec<PathBuf> {
    toml_files("mechanisms", 13)
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
            vec!["sensitivities", path, "-f", "csv"],
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

/// The library's file of the worksheet's four-bar.
fn four_bar_file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms/four_bar.toml")
}

/// CSV read back: the header's columns and the rows' numbers (after the
/// row name, if `named`).
fn csv(out: &Output, named: bool) -> (Vec<String>, Vec<Vec<f64>>) {
    assert!(out.status.success(), "{}", text(&out.stderr));
    let csv = text(&out.stdout);
    let mut lines = csv.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| {
            (l.split(',').skip(usize::from(named)))
                .map(|x| x.parse().unwrap())
                .collect()
        })
        .collect();
    (header, rows)
}

/// The compiled four-bar as the tool sees the file: the pose it assembles
/// at the driver's `at`, and the sweep's options, its start at `from` and
/// its range.
fn worksheet_sweep() -> (FourBar, SweepOptions, SVector<f64, 2>, (f64, f64)) {
    let file = MechanismFile::read(four_bar_file()).unwrap();
    let driver = file.driver("theta2").unwrap();
    let bar = FourBar::WORKSHEET;
    let start = worksheet_at();
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
    let from = back.poses.last().unwrap().u;
    (bar, options, from, (driver.from.value, driver.to.value))
}

/// The compiled four-bar analysed at the file's `at`, from the file's
/// assembly, at the file's rate and acceleration.
fn worksheet_at() -> Analysis<2, 1, [Vector2<f64>; 5]> {
    let file = MechanismFile::read(four_bar_file()).unwrap();
    let driver = file.driver("theta2").unwrap();
    let bar = FourBar::WORKSHEET;
    let pick = file
        .assembly
        .as_ref()
        .unwrap()
        .pick::<2>(&["theta3", "theta4"])
        .unwrap();
    let mode = bar.assemble(&vector![driver.at.value], &pick).unwrap();
    bar.analyze(
        &mode.u,
        &vector![driver.at.value],
        &vector![driver.rate.value],
        &vector![driver.acceleration.value],
        &Options::default(),
    )
    .unwrap()
}

/// The worksheet's four-bar swept by the tool, read back from CSV, is the
/// compiled four-bar's sweep from the same assembly, every number to the bit.
#[test]
fn the_sweep_in_csv_is_the_compiled_sweep_to_the_bit() {
    let path = four_bar_file();
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
    let (bar, options, from, to) = worksheet_sweep();
    let sweep = bar
        .sweep(
            &from,
            &Drive::Line {
                from: vector![to.0],
                to: vector![to.1],
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

/// `expand --expanded` prints the code the attribute generates: for the
/// quick return, exactly the file under `tests/files/expanded/`, which the facade's tests compile and hold equal
/// to the file read at run time, to the bit. After a deliberate change to
/// the generated code, `LINKAGE_BLESS=1` rewrites them.
#[test]
fn expand_expanded_is_the_code_the_attribute_generates() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let name = "quick_return";
    let file = format!("mechanisms/{name}.toml");
    let out = (tool().args(["expand", "--expanded", &file]))
        .current_dir(&root)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", text(&out.stderr));
    let rust = text(&out.stdout);
    let committed = root.join(format!("tests/files/expanded/{name}.rs"));
    if std::env::var_os("LINKAGE_BLESS").is_some() {
        std::fs::write(&committed, &rust).unwrap();
    }
    let expected = std::fs::read_to_string(&committed).unwrap();
    assert!(
        rust == expected,
        "`linkage expand --expanded {file}` is not {}: review the change, then rerun with LINKAGE_BLESS=1",
        committed.display()
    );
    // The attribute's own output: the struct and every item it adds.
    for item in [
        "pub struct ",
        "impl ::linkage::Kernels<",
        "impl ::linkage::Sensitivities<",
        "pub const FILE: ",
    ] {
        assert!(rust.contains(item), "{item} in {file}'s expansion");
    }
}

/// The tool's sensitivities of the worksheet's four-bar are the compiled
/// four-bar's at the same pose, every number to the bit.
#[test]
fn the_sensitivities_are_the_compiled_ones_to_the_bit() {
    let path = four_bar_file();
    let out = run(&["sensitivities", path.to_str().unwrap(), "-f", "csv"]);
    let (header, rows) = csv(&out, true);
    assert_eq!(header, ["quantity", "d/dl1", "d/dl2", "d/dl3", "d/dl4"]);
    let s = FourBar::WORKSHEET
        .sensitivities_of(&worksheet_at(), &Options::default())
        .unwrap();
    // theta3, theta3', theta3'', theta4, …, then the points.
    let mut expected = Vec::new();
    for k in 0..2 {
        for m in [&s.u, &s.udot, &s.uddot] {
            expected.push((0..4).map(|j| m[(k, j)]).collect::<Vec<_>>());
        }
    }
    for p in 0..5 {
        for level in [&s.points, &s.point_velocities, &s.point_accelerations] {
            for axis in [0, 1] {
                expected.push(level.iter().map(|column| column[p][axis]).collect());
            }
        }
    }
    assert_eq!(rows.len(), expected.len());
    for (row, e) in rows.iter().zip(&expected) {
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(row), bits(e), "{row:?} {e:?}");
    }
    // Chosen parameters, in the order asked.
    let out = run(&[
        "sensitivities",
        path.to_str().unwrap(),
        "-f",
        "csv",
        "-p",
        "l3",
        "-p",
        "l1",
    ]);
    let (header, chosen) = csv(&out, true);
    assert_eq!(header, ["quantity", "d/dl3", "d/dl1"]);
    assert_eq!(chosen[0], [rows[0][2], rows[0][0]]);
}

/// The tool's tolerance bands of the worksheet's four-bar are the compiled
/// four-bar's: the largest worst case, RSS and σ of each quantity, and the
/// pose where it is.
#[test]
fn the_tolerance_bands_are_the_compiled_ones() {
    use linkage::tolerance::{self, Output, Tolerance, Tolerances};
    use linkage::watch::{Axis, Of};
    let path = four_bar_file();
    let out = run(&[
        "tolerance",
        path.to_str().unwrap(),
        "-t",
        "l2=0.05",
        "-t",
        "l3=normal:0.02",
        "-q",
        "theta4",
        "-q",
        "C.y''",
        "-q",
        "C.path",
        "--steps",
        "72",
        "-f",
        "csv",
    ]);
    let (header, rows) = csv(&out, true);
    assert_eq!(
        header,
        [
            "quantity",
            "at theta2",
            "value",
            "worst case",
            "RSS",
            "σ",
            "share of l2",
            "share of l3"
        ]
    );
    let (bar, options, from, (a, b)) = worksheet_sweep();
    let drive = Drive::Line {
        from: vector![a],
        to: vector![b],
        steps: 72,
    };
    let tolerances = Tolerances::new([
        Tolerance::EXACT,
        Tolerance::Band(0.05),
        Tolerance::Normal(0.02),
        Tolerance::EXACT,
    ])
    .unwrap();
    let outputs = [
        Output::coordinate("theta4", Of::Position),
        Output::point("C", Axis::Y, Of::Acceleration),
        Output::path("C"),
    ];
    let cycle = tolerance::cycle(&bar, &from, &drive, &options, &outputs, &tolerances).unwrap();
    assert_eq!(rows.len(), 3);
    for (row, band) in rows.iter().zip(&cycle.bands) {
        let (k, spread) = band.largest().unwrap();
        let shares = tolerances.contributions(&band.gradient[k].unwrap());
        let expected = [
            band.v[k][0],
            band.value[k],
            spread.worst_case,
            spread.rss,
            spread.sigma,
            shares[1],
            shares[2],
        ];
        for (x, y) in row.iter().zip(expected) {
            assert!(
                (x - y).abs() <= 2.0 * f64::EPSILON * y.abs(),
                "{}: {row:?} against {expected:?}",
                band.name
            );
        }
    }
}

/// A path synthesis from the command line finds the worksheet's
/// dimensions again from five points of its coupler's midpoint; a targets
/// file with a mistake says where (status 1), bounds the wrong way round
/// are a command-line mistake (status 2).
#[test]
fn synthesis_finds_the_dimensions_that_traced_the_targets() {
    let bar = FourBar::WORKSHEET;
    let (_, options, from, _) = worksheet_sweep();
    let drive = Drive::Line {
        from: vector![0.3],
        to: vector![0.3 + 4.0 * std::f64::consts::TAU / 5.0],
        steps: 4,
    };
    let sweep = bar.sweep(&from, &drive, &options).unwrap();
    let dir = std::env::temp_dir().join(format!("linkage-synthesis-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let targets = dir.join("targets.txt");
    let mut lines = String::from("# x, y of G3\n");
    for pose in &sweep.poses {
        let g3 = bar.point_positions(&pose.u, &pose.v)[FourBar::G3];
        lines += &format!("{:e}, {:e}\n", g3.x, g3.y);
    }
    std::fs::write(&targets, lines).unwrap();
    let path = four_bar_file();
    let (path, targets) = (path.to_str().unwrap(), targets.to_str().unwrap());
    let args = [
        "synthesize",
        path,
        "--path",
        "G3",
        "--targets",
        targets,
        "--free",
        "l2=10:30",
        "--free",
        "l3=30:70",
        "--free",
        "l4=40:80",
        "--precision-points",
        "--starts",
        "16",
        "-f",
        "csv",
    ];
    let (header, rows) = csv(&run(&args), true);
    assert_eq!(&header[..5], ["design", "l1", "l2", "l3", "l4"]);
    assert!(!rows.is_empty());
    for row in &rows {
        let error = (0..4)
            .map(|j| (row[j] - [bar.l1, bar.l2, bar.l3, bar.l4][j]).abs())
            .fold(0.0, f64::max);
        assert!(error < 1e-9, "{row:?}");
    }
    std::fs::write(targets, "1.0, 2.0\n3.0, y\n").unwrap();
    let out = run(&args);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("targets.txt:2: `y` is not a finite number"),
        "{}",
        text(&out.stderr)
    );
    let mut wrong = args;
    wrong[7] = "l2=30:10";
    let out = run(&wrong);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("the lower bound must be below the upper"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A folder of its own for one test, removed at the end.
struct Folder(PathBuf);

impl Folder {
    fn new(name: &str) -> Folder {
        let path = std::env::temp_dir().join(format!("linkage-cli-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(path.join("work")).unwrap();
        Folder(path)
    }

    /// Every entry under the folder, with the contents of its files.
    fn listing(&self) -> Vec<(String, Option<Vec<u8>>)> {
        fn walk(dir: &Path, root: &Path, out: &mut Vec<(String, Option<Vec<u8>>)>) {
            for entry in std::fs::read_dir(dir).unwrap() {
                let entry = entry.unwrap();
                let path = entry.path();
                let kind = entry.file_type().unwrap();
                let name = path.strip_prefix(root).unwrap().display().to_string();
                if kind.is_dir() {
                    out.push((format!("{name}/"), None));
                    walk(&path, root, out);
                } else if kind.is_file() {
                    out.push((name, Some(std::fs::read(&path).unwrap())));
                } else {
                    out.push((name, None));
                }
            }
        }
        let mut out = Vec::new();
        walk(&self.0, &self.0, &mut out);
        out.sort();
        out
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs the tool in `dir` and waits at most a minute for it (a tool that
/// opened the named pipe would wait for a writer forever).
fn run_in(dir: &Path, args: &[&str]) -> Output {
    let mut child = tool()
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let started = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if started.elapsed() > std::time::Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("linkage {args:?} did not end: it opened something it was not given");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// The tool reads the file it is given and writes `--output`, nothing
/// else, whatever the file says: a title, units, values, unknown keys and
/// tables that are paths — to a named pipe beside it (which would block a
/// reader), to a file that must stay as it is, to one that must not
/// appear, to /etc/passwd — are text. Every command, on a valid file and
/// on one with mistakes; afterwards the folder holds the file, the
/// outputs asked for, and what was there before, unchanged.
#[test]
fn a_file_makes_the_tool_read_and_write_only_its_paths() {
    let folder = Folder::new("paths");
    let work = folder.0.join("work");
    std::fs::write(folder.0.join("kept.txt"), "as it was\n").unwrap();
    // A named pipe where there is mkfifo; a plain file elsewhere.
    let made = Command::new("mkfifo").arg(folder.0.join("pipe")).status();
    if !made.is_ok_and(|s| s.success()) {
        std::fs::write(folder.0.join("pipe"), "a pipe\n").unwrap();
    }
    let four_bar = include_str!("../../mechanisms/four_bar.toml");
    let valid = four_bar
        .replace(
            "title = \"The four-bar of the Maple worksheet\"",
            "title = \"../pipe\\n}\\nfn main() { std::fs::write(\\\"../written.txt\\\", \\\"\\\").unwrap(); }\"",
        )
        .replace("[drawing]", "[drawing]\n# ../kept.txt /etc/passwd");
    std::fs::write(work.join("m.toml"), &valid).unwrap();
    let wrong = format!(
        "include = \"../pipe\"\noutput = \"../written.txt\"\n{}",
        valid
            .replace("length_unit = \"mm\"", "length_unit = \"/etc/passwd\"")
            .replace("l1 = \"80 mm\"", "l1 = \"../kept.txt\"")
            .replace(
                "[drawing]",
                "[paths]\npath = \"/etc/passwd\"\n[drawing]\nfile = \"../written.txt\""
            )
    );
    std::fs::write(work.join("wrong.toml"), &wrong).unwrap();
    let before = folder.listing();
    let commands: [&[&str]; 7] = [
        &["check", "m.toml", "-o", "check.txt"],
        &["analyze", "m.toml", "-o", "analyze.txt"],
        &["sweep", "m.toml", "--steps", "12", "-o", "sweep.txt"],
        &["extremes", "m.toml", "-o", "extremes.txt"],
        &["draw", "m.toml", "-o", "m.svg"],
        &["expand", "m.toml", "-o", "m.rs"],
        &["check", "m.toml"],
    ];
    let mut written = Vec::new();
    for args in commands {
        let out = run_in(&work, args);
        assert!(
            out.status.success(),
            "linkage {args:?}: {}",
            text(&out.stderr)
        );
        if let Some(k) = args.iter().position(|a| *a == "-o") {
            written.push(format!("work/{}", args[k + 1]));
        }
    }
    for command in ["check", "analyze", "sweep", "extremes", "draw", "expand"] {
        let out = run_in(&work, &[command, "wrong.toml", "-o", "wrong.out"]);
        assert_eq!(
            out.status.code(),
            Some(1),
            "{command}: {}",
            text(&out.stderr)
        );
        assert!(
            text(&out.stderr).contains("wrong.toml:1:1"),
            "{}",
            text(&out.stderr)
        );
    }
    // The title, in the Rust `expand` writes, is comment: each of its
    // lines a comment line, none of them code.
    let rust = std::fs::read_to_string(work.join("m.rs")).unwrap();
    assert!(rust.contains("/// fn main() { std::fs::write("), "{rust}");
    assert!(!rust.lines().any(|l| l.starts_with("fn main")), "{rust}");
    let after = folder.listing();
    let mut expected: Vec<String> = before.iter().map(|(n, _)| n.clone()).collect();
    expected.extend(written);
    expected.sort();
    let names: Vec<String> = after.iter().map(|(n, _)| n.clone()).collect();
    assert_eq!(names, expected);
    for (name, contents) in &before {
        let now = after.iter().find(|(n, _)| n == name).map(|(_, c)| c);
        assert_eq!(now, Some(contents), "{name} changed");
    }
}

/// The topology files (joints and links) of `mechanisms/joints/`.
fn topologies() -> Vec<PathBuf> {
    toml_files("mechanisms/joints", 5)
}

#[test]
fn every_topology_file_generates_its_equations_and_runs_every_command() {
    for file in topologies() {
        let path = file.to_str().unwrap();
        for args in [
            vec!["check", path],
            vec!["equations", path],
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
        // The generated equations are a mechanism file that reads.
        let equations = text(&run(&["equations", path]).stdout);
        MechanismFile::parse(&equations).unwrap();
    }
    // A mechanism file is not a topology.
    let out = run(&["equations", four_bar_file().to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn a_topologys_mistake_is_located_at_its_culprit() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms/joints/four_bar.toml");
    let good = std::fs::read_to_string(file).unwrap();
    let bad = good.replace("D = [80, 0]", "D = [80, 0]\nE = [1, 2]");
    let line = bad.lines().position(|l| l.starts_with("E = ")).unwrap() + 1;
    let out = with_input(&["check", "-"], &bad);
    assert_eq!(out.status.code(), Some(1));
    let message = text(&out.stderr);
    assert!(
        message.contains("joint `E` is on no link")
            && message.contains(&format!("<stdin>:{line}:1")),
        "{message}"
    );
    assert_eq!(message.matches("error").count(), 1, "{message}");
}

/// A pyslvs expression imported as a topology file analyses; exported
/// again it is the same expression; without its input it is refused.
#[test]
fn import_and_export_carry_a_pyslvs_expression() {
    let expression = "M[J[R, color[Green], P[0.0, 0.0], L[ground, L1]], J[R, color[Green], P[12.92, 32.53], L[L1, L2]], J[R, color[Green], P[73.28, 67.97], L[L2, L3]], J[R, color[Green], P[33.3, 66.95], L[L2]], J[R, color[Green], P[90.0, 0.0], L[ground, L3]]]";
    let dir = std::env::temp_dir().join(format!("linkage-import-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let source = dir.join("crank_rocker.txt");
    std::fs::write(&source, expression).unwrap();
    let topology = dir.join("crank_rocker.toml");
    let (source, topology) = (source.to_str().unwrap(), topology.to_str().unwrap());
    let out = run(&[
        "import",
        "pyslvs",
        source,
        "--input",
        "0,1",
        "--name",
        "CrankRocker",
        "-o",
        topology,
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let out = run(&["analyze", topology, "-f", "csv"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let out = run(&["export", "pyslvs", topology]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        format!("{expression}\n# inputs: (0, 1)\n")
    );
    let out = run(&["export", "pylinkage", topology]);
    assert!(out.status.success() && text(&out.stdout).contains("\"motor_joint\": \"J0\""));
    let out = run(&["import", "pyslvs", source]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("0 driver(s)"),
        "{}",
        text(&out.stderr)
    );
    let out = run(&["import", "pyslvs", source, "--input", "0,7"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("names a joint the expression does not have"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A topology whose given lengths cannot close its loop says which loop,
/// and by how much, as drawn.
#[test]
fn a_topology_that_does_not_close_names_its_loop() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms/joints/four_bar.toml");
    let topology = std::fs::read_to_string(file)
        .unwrap()
        .replace("D-C = 70", "D-C = 10");
    let out = with_input(&["analyze", "-"], &topology);
    assert_eq!(out.status.code(), Some(3));
    let message = text(&out.stderr);
    assert!(
        message.contains("does not assemble")
            && message.contains("the loop closing at joint `C` misses by 46.26"),
        "{message}"
    );
}

/// The tool run with `input` on its standard input.
fn with_input(args: &[&str], input: &str) -> Output {
    let mut child = tool()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    child.wait_with_output().unwrap()
}

/// `linkage serve` answers a browser's requests for the page's files on
/// the loopback interface, with their content types, and nothing outside
/// its folder; a folder without the built engine is refused with the
/// command that builds it.
#[test]
fn serve_gives_the_pages_files_and_nothing_else() {
    use std::io::{BufRead, BufReader, Read};
    let dir = std::env::temp_dir().join(format!("linkage-serve-test-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("pkg")).unwrap();
    std::fs::write(dir.join("index.html"), "<!doctype html><title>page</title>").unwrap();
    let refused = run(&["serve", dir.to_str().unwrap(), "--port", "0"]);
    assert_eq!(refused.status.code(), Some(1));
    assert!(
        text(&refused.stderr).contains("web/build.sh"),
        "{}",
        text(&refused.stderr)
    );
    std::fs::write(dir.join("pkg/linkage_web_bg.wasm"), b"\0asm\x01\0\0\0").unwrap();
    let mut server = tool()
        .args(["serve", dir.to_str().unwrap(), "--port", "0"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(server.stderr.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    let address = first
        .split("http://")
        .nth(1)
        .and_then(|rest| rest.split('/').next())
        .unwrap_or_else(|| panic!("no address in {first:?}"))
        .to_owned();
    let get = |path: &str| -> String {
        let mut stream = std::net::TcpStream::connect(&address).unwrap();
        write!(stream, "GET {path} HTTP/1.1\r\nHost: {address}\r\n\r\n").unwrap();
        let mut answer = Vec::new();
        stream.read_to_end(&mut answer).unwrap();
        String::from_utf8_lossy(&answer).into_owned()
    };
    // A second server on the port taken: a file-and-system failure (4).
    let port = address.rsplit(':').next().unwrap();
    let taken = run(&["serve", dir.to_str().unwrap(), "--port", port]);
    assert_eq!(taken.status.code(), Some(4), "{}", text(&taken.stderr));
    assert!(text(&taken.stderr).contains("cannot listen"));
    let page = get("/?selftest");
    let wasm = get("/pkg/linkage_web_bg.wasm");
    let outside = get("/../Cargo.toml");
    let missing = get("/nothing.js");
    server.kill().unwrap();
    server.wait().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(page.starts_with("HTTP/1.1 200 OK\r\n"), "{page}");
    assert!(page.contains("Content-Type: text/html") && page.ends_with("<title>page</title>"));
    assert!(
        wasm.contains("Content-Type: application/wasm\r\n")
            && wasm.contains("Content-Length: 8\r\n")
    );
    assert!(outside.starts_with("HTTP/1.1 404"), "{outside}");
    assert!(missing.starts_with("HTTP/1.1 404"), "{missing}");
}
