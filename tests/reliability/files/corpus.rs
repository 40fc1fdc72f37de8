//! The library of mechanism files, and mechanism files mutated: their
//! values replaced by awkward ones (numbers huge, tiny, not finite, with
//! unknown or misplaced units, paths), keys deleted, duplicated, renamed
//! and invented, drives that do not assemble, equations mutated in place,
//! and files made up from the grammar.

use super::generate::{self, Made};
use super::mutate::{self, UNICODE};
use super::random::Rng;

/// The 13 files of `mechanisms/`.
pub(crate) const LIBRARY: &[(&str, &str)] = &[
    ("boom", include_str!("../../../mechanisms/boom.toml")),
    ("coupler", include_str!("../../../mechanisms/coupler.toml")),
    (
        "five_bar",
        include_str!("../../../mechanisms/five_bar.toml"),
    ),
    (
        "four_bar",
        include_str!("../../../mechanisms/four_bar.toml"),
    ),
    (
        "jansen_leg",
        include_str!("../../../mechanisms/jansen_leg.toml"),
    ),
    (
        "quick_return",
        include_str!("../../../mechanisms/quick_return.toml"),
    ),
    ("shaper", include_str!("../../../mechanisms/shaper.toml")),
    ("six_bar", include_str!("../../../mechanisms/six_bar.toml")),
    (
        "slider_crank",
        include_str!("../../../mechanisms/slider_crank.toml"),
    ),
    (
        "slider_driven",
        include_str!("../../../mechanisms/slider_driven.toml"),
    ),
    (
        "stephenson_three",
        include_str!("../../../mechanisms/stephenson_three.toml"),
    ),
    ("trammel", include_str!("../../../mechanisms/trammel.toml")),
    (
        "watt_six_bar",
        include_str!("../../../mechanisms/watt_six_bar.toml"),
    ),
];

/// The equations of a library file and the byte range of their text.
pub(crate) fn equations(file: &str) -> (std::ops::Range<usize>, &str) {
    let start = file.find("'''").expect("the equations' literal string") + 3;
    let end = start + file[start..].find("'''").expect("its end");
    (start..end, &file[start..end])
}

/// The parameters of a library file, as their names and values in the
/// file's units (for the equations used as a text, not a file).
pub(crate) fn parameters(file: &str) -> Vec<(String, f64)> {
    let parsed = linkage::file::MechanismFile::parse(file).expect("a library file is valid");
    (parsed.parameters.iter())
        .map(|p| (p.name.text.clone(), p.quantity.value))
        .collect()
}

/// Values a key may be given: awkward numbers, units unknown, misplaced
/// or mangled, strings that are paths, and values of every TOML type.
const VALUES: &[&str] = &[
    "0",
    "-1",
    "1e999",
    "-1e999",
    "nan",
    "inf",
    "-inf",
    "+nan",
    "1e-400",
    "5e-324",
    "1.7976931348623157e308",
    "\"80 mm\"",
    "\"80 furlong\"",
    "\"80 MM\"",
    "\"80mm\"",
    "\"80 m m\"",
    "\"nan mm\"",
    "\"NaN\"",
    "\"inf deg\"",
    "\"-inf rad\"",
    "\"1e400 mm\"",
    "\"1e-400 rad\"",
    "\"-0 deg\"",
    "\"1e308 km\"",
    "\"1e308 ft\"",
    "\"1e307 rev\"",
    "\"400 rpm\"",
    "\"400 rpm^2\"",
    "\"9.81 m/s^2\"",
    "\"1 rev\"",
    "\"1 rev/s\"",
    "\"3 rad/s^2\"",
    "\"12 in\"",
    "\"0x10 mm\"",
    "\"1_000 mm\"",
    "\"\"",
    "\" \"",
    "\"mm\"",
    "\"80\"",
    "\"1 deg deg\"",
    "\"1 µm\"",
    "\"1 mm/s/s\"",
    "\"1e99999999999999999999 mm\"",
    "\"θ\"",
    "\"../../etc/passwd\"",
    "\"/etc/passwd\"",
    "\"/dev/zero\"",
    "\"/dev/stdin\"",
    "\"~/.ssh/id_rsa\"",
    "\"file:///etc/shadow\"",
    "\"C:\\\\Windows\\\\win.ini\"",
    "'../../../../../../tmp/linkage-fuzz-written'",
    "true",
    "[]",
    "[1, 2]",
    "[\"A\", \"B\"]",
    "[[\"A\", \"B\"]]",
    "[0, 0]",
    "[\"80 mm\", 0]",
    "[\"nan mm\", \"1e999 mm\"]",
    "{}",
    "{ x = 1 }",
    "{ theta3 = \"70 deg\" }",
    "{ B = [0, 0] }",
    "1979-05-27T07:32:00Z",
    "'''x'''",
    "\"\"\"u = [x], v = [t], closure = [x - t]\"\"\"",
    "99999999999999999999",
    "18446744073709551616",
    "4294967296",
    "1000001",
    "1000000",
    "-9223372036854775808",
    "0.5",
    "360",
    "1",
    "2",
    "65536",
    "65537",
];

/// Keys of the format, and keys it does not have (some that other
/// formats take as paths).
const KEYS: &[&str] = &[
    "name",
    "title",
    "length_unit",
    "equations",
    "parameters",
    "drive",
    "assembly",
    "drawing",
    "from",
    "to",
    "steps",
    "rate",
    "acceleration",
    "at",
    "index",
    "near",
    "points",
    "ground",
    "links",
    "plates",
    "sliders",
    "velocities",
    "accelerations",
    "trace",
    "velocity_scale",
    "acceleration_scale",
    "point",
    "angle",
    "along",
    "slot",
    "include",
    "path",
    "file",
    "output",
    "import",
    "extends",
    "\"../../etc/passwd\"",
    "θ",
    "l1",
    "theta2",
    "theta3",
];

/// Table headers, the format's and others.
const HEADERS: &[&str] = &[
    "[parameters]",
    "[drive]",
    "[drive.theta2]",
    "[drive.theta]",
    "[drive.s]",
    "[drive.bogus]",
    "[drive.l1]",
    "[drive.theta2.extra]",
    "[[drive]]",
    "[assembly]",
    "[assembly.near]",
    "[assembly.points]",
    "[drawing]",
    "[drawing.ground]",
    "[[drawing.sliders]]",
    "[include]",
    "[parameters.l1]",
    "[\"../../etc/passwd\"]",
    "[θ]",
];

/// The lines of `text` that hold a key and its value (`key = value`),
/// outside the equations' string.
fn value_lines(lines: &[String]) -> Vec<usize> {
    let mut inside = false;
    let mut out = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let quotes = line.matches("'''").count();
        if !inside && quotes == 0 && line.contains('=') && !line.trim_start().starts_with('#') {
            out.push(k);
        }
        if quotes % 2 == 1 {
            inside = !inside;
        }
    }
    out
}

/// The key and value of a line `key = value # comment`.
fn split(line: &str) -> Option<(&str, &str)> {
    let eq = line.find('=')?;
    Some((&line[..eq], &line[eq + 1..]))
}

/// A number written in the line's value, scaled by a factor near 1 (or
/// its sign changed): the file stays valid, its mechanism changes.
fn perturb(rng: &mut Rng, value: &str) -> String {
    let tokens = mutate::tokens(value);
    let numbers: Vec<usize> = (0..tokens.len())
        .filter(|&k| tokens[k].starts_with(|c: char| c.is_ascii_digit()))
        .filter(|&k| tokens[k].parse::<f64>().is_ok())
        .collect();
    if numbers.is_empty() {
        return value.to_string();
    }
    let mut tokens = tokens;
    let k = *rng.pick(&numbers);
    let x: f64 = tokens[k].parse().unwrap_or(1.0);
    let y = match rng.below(4) {
        0 => x * (0.5 + rng.unit()),
        1 => x * (0.9 + 0.2 * rng.unit()),
        2 => x * 10f64.powf(rng.unit() * 6.0 - 3.0),
        _ => x + 1.0,
    };
    tokens[k] = format!("{}", y.abs());
    tokens.concat()
}

/// One structured mutation of a file's lines.
fn mutate_lines(rng: &mut Rng, lines: &mut Vec<String>, library: &[(&str, &str)]) {
    let values = value_lines(lines);
    let line = |rng: &mut Rng| {
        if values.is_empty() {
            0
        } else {
            *rng.pick(&values)
        }
    };
    match rng.below(14) {
        // A value replaced by an awkward one.
        0..=3 => {
            let k = line(rng);
            if let Some((key, _)) = split(&lines[k].clone()) {
                let value = if rng.one_in(6) {
                    format!(
                        "\"{} {}\"",
                        mutate::number(rng),
                        rng.pick(&["mm", "deg", "rpm", "m", "rad/s", "furlong", ""])
                    )
                } else {
                    rng.pick(VALUES).to_string()
                };
                lines[k] = format!("{key}= {value}");
            }
        }
        // A number nudged: a valid file of another mechanism.
        4 | 5 => {
            let k = line(rng);
            if let Some((key, value)) = split(&lines[k].clone()) {
                lines[k] = format!("{key}={}", perturb(rng, value));
            }
        }
        // A line deleted, duplicated or moved.
        6 => {
            if lines.len() > 1 {
                let k = line(rng);
                lines.remove(k.min(lines.len() - 1));
            }
        }
        7 => {
            let k = line(rng).min(lines.len().saturating_sub(1));
            if let Some(copy) = lines.get(k).cloned() {
                let at = if rng.one_in(2) {
                    k
                } else {
                    rng.below(lines.len())
                };
                lines.insert(at, copy);
            }
        }
        // A key renamed.
        8 => {
            let k = line(rng);
            if let Some((_, value)) = split(&lines[k].clone()) {
                lines[k] = format!("{} ={value}", rng.pick(KEYS));
            }
        }
        // A key or a table added.
        9 => {
            let at = rng.below(lines.len() + 1);
            let new = if rng.one_in(3) {
                rng.pick(HEADERS).to_string()
            } else {
                format!("{} = {}", rng.pick(KEYS), rng.pick(VALUES))
            };
            lines.insert(at, new);
        }
        // The drive stretched to where the mechanism may not assemble.
        10 => {
            let drive: Vec<usize> = values
                .iter()
                .copied()
                .filter(|&k| {
                    let key = lines[k].split('=').next().unwrap_or("").trim();
                    ["from", "to", "at"].contains(&key)
                })
                .collect();
            if !drive.is_empty() {
                let k = *rng.pick(&drive);
                if let Some((key, value)) = split(&lines[k].clone()) {
                    let unit = if value.contains("deg")
                        || value.contains("rad")
                        || value.contains("rev")
                    {
                        rng.pick(&["deg", "rad", "rev"]).to_string()
                    } else {
                        rng.pick(&["mm", "m", "cm", ""]).to_string()
                    };
                    let x = (rng.unit() * 2.0 - 1.0) * 10f64.powi(rng.between(0, 8) as i32);
                    lines[k] = format!("{key}= \"{x} {unit}\"");
                }
            }
        }
        // A table of another file, or another file's line.
        11 => {
            let (_, other) = rng.pick(library);
            let other: Vec<&str> = other.lines().collect();
            let from = rng.below(other.len());
            let n = rng.few(12).min(other.len() - from);
            let at = rng.below(lines.len() + 1);
            for (j, l) in other[from..from + n].iter().enumerate() {
                lines.insert(at + j, l.to_string());
            }
        }
        // Unicode in a line.
        12 => {
            let k = rng
                .below(lines.len().max(1))
                .min(lines.len().saturating_sub(1));
            if let Some(l) = lines.get_mut(k) {
                let mut cut = rng.below(l.len() + 1);
                while !l.is_char_boundary(cut) {
                    cut -= 1;
                }
                let c = *rng.pick(UNICODE);
                l.insert_str(cut, c);
            }
        }
        // The lines shuffled a little.
        _ => {
            if lines.len() > 1 {
                let (a, b) = (rng.below(lines.len()), rng.below(lines.len()));
                lines.swap(a, b);
            }
        }
    }
}

/// A library file mutated: its lines, its equations or its text.
pub(crate) fn mutated_file(rng: &mut Rng) -> String {
    let (_, original) = rng.pick(LIBRARY);
    let mut text = original.to_string();
    for _ in 0..rng.few(5) {
        text = mutate::capped(match rng.below(10) {
            0..=4 => {
                let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
                mutate_lines(rng, &mut lines, LIBRARY);
                let mut joined = lines.join("\n");
                joined.push('\n');
                joined
            }
            5..=7 => match text
                .find("'''")
                .and_then(|s| text[s + 3..].find("'''").map(|e| (s + 3, s + 3 + e)))
            {
                Some((start, end)) => {
                    let inner = mutate::mutate(rng, &text[start..end]).replace("'''", "''");
                    format!("{}{inner}{}", &text[..start], &text[end..])
                }
                None => mutate::mutate(rng, &text),
            },
            _ => mutate::mutate(rng, &text),
        });
    }
    text
}

/// A library file with a few of its numbers nudged: a valid file, most
/// of the time, of a mechanism that may not assemble, or not over the
/// whole drive, or not at `at`.
pub(crate) fn nudged_file(rng: &mut Rng) -> String {
    let (_, original) = rng.pick(LIBRARY);
    let mut lines: Vec<String> = original.lines().map(str::to_string).collect();
    let values = value_lines(&lines);
    for _ in 0..rng.few(4) {
        let k = *rng.pick(&values);
        if let Some((key, value)) = split(&lines[k].clone()) {
            lines[k] = format!("{key}={}", perturb(rng, value));
        }
    }
    let mut text = lines.join("\n");
    text.push('\n');
    text
}

/// A value of `kind`, with a unit now and then.
fn quantity(rng: &mut Rng, angle: bool) -> String {
    let x = (rng.unit() * 2.0 - 1.0) * 10f64.powi(rng.between(0, 3) as i32);
    match rng.below(4) {
        0 => format!("{x}"),
        1 if angle => format!("\"{x} deg\""),
        1 => format!("\"{x} mm\""),
        2 if angle => format!("\"{x} rad\""),
        2 => format!("\"{x} cm\""),
        _ => rng.pick(VALUES).to_string(),
    }
}

/// A file made up from the grammar: made-up equations, parameters with
/// units, a drive per coordinate of v (now and then one short or one
/// more), an assembly and a drawing.
pub(crate) fn made_file(rng: &mut Rng) -> String {
    let Made {
        text,
        u,
        v,
        parameters,
        points,
    } = generate::mechanism(rng);
    let mut file = String::new();
    file.push_str("name = \"Made\"\n");
    if rng.one_in(3) {
        file.push_str(&format!(
            "length_unit = \"{}\"\n",
            rng.pick(&["mm", "m", "cm", "in", "ft", "deg", "furlong", ""])
        ));
    }
    file.push_str(&format!("equations = '''\n{text}'''\n\n[parameters]\n"));
    for p in &parameters {
        if rng.one_in(20) {
            continue;
        }
        let x = generate::value(rng);
        let written = if !x.is_finite() {
            rng.pick(&["nan", "inf", "-inf", "\"nan mm\""]).to_string()
        } else if rng.one_in(2) {
            format!("\"{x} mm\"")
        } else {
            format!("{x:e}")
        };
        file.push_str(&format!("{p} = {written}\n"));
    }
    let mut drivers: Vec<String> = v.clone();
    if rng.one_in(10) {
        drivers.pop();
    }
    if rng.one_in(10) {
        drivers.push(rng.pick(&["extra", "theta3", "l0"]).to_string());
    }
    for d in &drivers {
        let angle = rng.one_in(2);
        file.push_str(&format!("\n[drive.{d}]\n"));
        let from = (rng.unit() * 2.0 - 1.0) * 3.0;
        let to = from + (rng.unit() * 2.0 - 1.0) * 6.0;
        let unit = if angle { "rad" } else { "m" };
        file.push_str(&format!("from = \"{from} {unit}\"\nto = \"{to} {unit}\"\n"));
        if rng.one_in(2) {
            file.push_str(&format!("steps = {}\n", rng.between(1, 400)));
        }
        if rng.one_in(2) {
            file.push_str(&format!("rate = {}\n", quantity(rng, angle)));
        }
        if rng.one_in(3) {
            file.push_str(&format!("acceleration = {}\n", quantity(rng, angle)));
        }
        if rng.one_in(2) {
            file.push_str(&format!("at = {}\n", quantity(rng, angle)));
        }
    }
    match rng.below(4) {
        0 => file.push_str(&format!("\n[assembly]\nindex = {}\n", rng.between(0, 3))),
        1 => {
            let sketch: Vec<String> = u
                .iter()
                .map(|n| format!("{n} = {}", (rng.unit() * 2.0 - 1.0) * 3.0))
                .collect();
            file.push_str(&format!(
                "\n[assembly]\nnear = {{ {} }}\n",
                sketch.join(", ")
            ));
        }
        2 if !points.is_empty() => {
            file.push_str(&format!(
                "\n[assembly]\npoints = {{ {} = [1, 2] }}\n",
                rng.pick(&points)
            ));
        }
        _ => {}
    }
    if rng.one_in(2) {
        let mut names: Vec<String> = points.clone();
        names.push("O".to_string());
        file.push_str("\n[drawing]\nground = { O = [0, 0] }\n");
        let a = rng.pick(&names).clone();
        let b = rng.pick(&names).clone();
        file.push_str(&format!("links = [[\"{a}\", \"{b}\"]]\n"));
        file.push_str(&format!("velocities = [\"{}\"]\n", rng.pick(&names)));
        file.push_str(&format!("trace = [\"{}\"]\n", rng.pick(&names)));
        if rng.one_in(3) {
            file.push_str(&format!(
                "sliders = [{{ point = \"{}\", angle = \"{} deg\" }}]\n",
                rng.pick(&names),
                rng.between(0, 360)
            ));
        }
    }
    if rng.one_in(3) {
        file = mutate::mutate_few(rng, &file);
    }
    file
}
