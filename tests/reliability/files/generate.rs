//! Mechanisms made up from the grammar: coordinates, parameters, points
//! and closure equations of every supported form — vector loops that
//! often assemble, and random expression trees that seldom do.

use super::mutate::{NUMBERS, depth, nested};
use super::random::Rng;

/// A mechanism's equations, made up.
pub(crate) struct Made {
    pub(crate) text: String,
    pub(crate) u: Vec<String>,
    pub(crate) v: Vec<String>,
    pub(crate) parameters: Vec<String>,
    pub(crate) points: Vec<String>,
}

const FUNCTIONS: &[&str] = &[
    "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "sqrt", "exp", "ln", "abs",
];

/// An ordinary number as the grammar writes it, or now and then an
/// awkward one.
fn literal(rng: &mut Rng) -> String {
    if rng.one_in(12) {
        return rng.pick(NUMBERS).to_string();
    }
    match rng.below(4) {
        0 => format!("{}", rng.between(0, 9)),
        1 => format!("{}.0", rng.between(1, 100)),
        2 => format!("{:.3}", rng.unit() * 4.0),
        _ => "0.5".to_string(),
    }
}

struct Names<'a> {
    u: &'a [String],
    v: &'a [String],
    p: &'a [String],
    points: &'a [String],
}

/// A random expression tree of at most `depth` levels.
fn tree(rng: &mut Rng, names: &Names<'_>, depth: usize) -> String {
    if depth == 0 || rng.one_in(4) {
        return match rng.below(9) {
            0 | 1 => rng.pick(names.u).clone(),
            2 => rng.pick(names.v).clone(),
            3 | 4 if !names.p.is_empty() => rng.pick(names.p).clone(),
            5 if !names.points.is_empty() => {
                format!("{}.{}", rng.pick(names.points), rng.pick(&["x", "y"]))
            }
            6 => rng
                .pick(&["PI", "TAU", "FRAC_PI_2", "std::f64::consts::E"])
                .to_string(),
            _ => literal(rng),
        };
    }
    let d = depth - 1;
    match rng.below(12) {
        0..=3 => {
            let op = rng.pick(&["+", "-", "*", "/"]);
            format!("{} {op} {}", tree(rng, names, d), tree(rng, names, d))
        }
        4 => format!("-{}", tree(rng, names, d)),
        5 => format!("({})", tree(rng, names, d)),
        6 | 7 => format!("({}).{}()", tree(rng, names, d), rng.pick(FUNCTIONS)),
        8 => {
            let n = *rng.pick(&[-3i64, -1, 0, 1, 2, 3, 5, 65536, -65537]);
            format!("({}).powi({n})", tree(rng, names, d))
        }
        9 => format!("({}).powf({})", tree(rng, names, d), tree(rng, names, d)),
        10 => {
            let f = rng.pick(&["atan2", "hypot"]);
            if rng.one_in(2) {
                format!("({}).{f}({})", tree(rng, names, d), tree(rng, names, d))
            } else {
                format!("{f}({}, {})", tree(rng, names, d), tree(rng, names, d))
            }
        }
        _ => format!("{}({})", rng.pick(FUNCTIONS), tree(rng, names, d)),
    }
}

/// A term of a vector loop: a length turning with an angle, or a length
/// along an axis; its x and y.
fn loop_term(rng: &mut Rng, length: &str, angle: &str) -> (String, String) {
    match rng.below(4) {
        0 => (
            format!("{length} * {angle}.cos()"),
            format!("{length} * {angle}.sin()"),
        ),
        1 => (
            format!("{length} * ({angle} + 0.5).cos()"),
            format!("{length} * ({angle} + 0.5).sin()"),
        ),
        2 => (angle.to_string(), "0.0".to_string()),
        _ => (format!("{length} * {angle}"), length.to_string()),
    }
}

/// A mechanism made up: `m` closure equations in `m` coordinates, driven
/// by `f`.
pub(crate) fn mechanism(rng: &mut Rng) -> Made {
    let m = *rng.pick(&[1, 1, 2, 2, 2, 2, 3, 3, 4, 4, 5, 6, 7, 8, 10]);
    let f = *rng.pick(&[1, 1, 1, 1, 2, 2, 3]);
    let stems = ["theta", "phi", "s", "x", "q"];
    let stem = rng.pick(&stems).to_string();
    let u: Vec<String> = (0..m).map(|k| format!("{stem}{}", k + 3)).collect();
    let v: Vec<String> = (0..f).map(|k| format!("drive{k}")).collect();
    let parameters: Vec<String> = (0..rng.between(0, 6)).map(|k| format!("l{k}")).collect();
    let mut points: Vec<String> = Vec::new();
    let mut point_text = Vec::new();
    for k in 0..rng.between(0, 4) {
        let names = Names {
            u: &u,
            v: &v,
            p: &parameters,
            points: &points,
        };
        let (x, y) = (tree(rng, &names, 2), tree(rng, &names, 2));
        let name = format!("P{k}");
        point_text.push(format!("{name} = ({x}, {y})"));
        points.push(name);
    }
    let names = Names {
        u: &u,
        v: &v,
        p: &parameters,
        points: &points,
    };
    let length = |rng: &mut Rng| {
        if !parameters.is_empty() && rng.one_in(2) {
            rng.pick(&parameters).clone()
        } else {
            format!("{}.0", rng.between(1, 90))
        }
    };
    let mut closure = Vec::new();
    let loops = rng.one_in(2);
    let mut k = 0;
    while closure.len() < m {
        if loops && closure.len() + 1 < m {
            // A vector loop: the driver's link, then the coordinates'.
            let l = length(rng);
            let (mut x, mut y) = loop_term(rng, &l, &v[k % f]);
            for j in [closure.len(), closure.len() + 1] {
                let l = length(rng);
                let (tx, ty) = loop_term(rng, &l, &u[j]);
                x = format!("{x} + {tx}");
                y = format!("{y} + {ty}");
            }
            closure.push(format!("{x} - {}", length(rng)));
            closure.push(format!("{y} - {}", literal(rng)));
        } else if loops {
            closure.push(format!("{} - {}", u[closure.len()], tree(rng, &names, 2)));
        } else {
            let d = rng.between(1, 4);
            closure.push(tree(rng, &names, d));
        }
        k += 1;
    }
    if rng.one_in(10) {
        let at = rng.below(closure.len());
        let d = depth(rng);
        closure[at] = nested(rng, &closure[at].clone(), d);
    }
    let mut text = format!("u = [{}],\nv = [{}],\n", u.join(", "), v.join(", "));
    if !point_text.is_empty() {
        text.push_str(&format!(
            "points = [\n    {},\n],\n",
            point_text.join(",\n    ")
        ));
    }
    text.push_str(&format!(
        "closure = [\n    {},\n],\n",
        closure.join(",\n    ")
    ));
    if !parameters.is_empty() && rng.one_in(4) {
        let mut listed: Vec<String> = parameters
            .iter()
            .filter(|_| rng.one_in(2))
            .cloned()
            .collect();
        if rng.one_in(4) {
            listed.push(rng.pick(&["zz", "theta3", "P0", "l1"]).to_string());
        }
        text.push_str(&format!("params = [{}],\n", listed.join(", ")));
    }
    Made {
        text,
        u,
        v,
        parameters,
        points,
    }
}

/// A parameter's value: ordinary, mostly, or awkward.
pub(crate) fn value(rng: &mut Rng) -> f64 {
    if rng.one_in(10) {
        return *rng.pick(&[
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            -1.0,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            1e300,
            1e-300,
            1e-170,
            1e170,
        ]);
    }
    10f64.powf(rng.unit() * 4.0 - 1.0)
}
