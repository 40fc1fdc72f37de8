//! Generated names never collide with the user's: structs named like the
//! generic parameters and helper types of the generated code (`M`, `F`,
//! `N`, `D`, `U`, `V`, `Self_`), and fields named like the generated
//! temporaries and locals (`s_theta3`, `c_theta3`, `psi`, `inverse`, ...),
//! compile and give the same numbers as the plain four-bar. (The error path
//! on such a struct is `tests/ui/struct_named_f.rs`.)

use linkage::prelude::*;

macro_rules! four_bar_named {
    ($name:ident) => {
        #[linkage::linkage(
                            u = [theta3, theta4],
                            v = [theta2],
                            points = [B = (l2 * theta2.cos(), l2 * theta2.sin())],
                            closure = [
                                l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
                                l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
                            ],
                        )]
        #[derive(Clone, Debug)]
        pub struct $name {
            pub l1: f64,
            pub l2: f64,
            pub l3: f64,
            pub l4: f64,
        }

        impl $name {
            pub fn worksheet() -> $name {
                $name {
                    l1: 80.0,
                    l2: 20.0,
                    l3: 50.0,
                    l4: 70.0,
                }
            }
        }
    };
}

four_bar_named!(M);
four_bar_named!(F);
four_bar_named!(N);
four_bar_named!(D);
four_bar_named!(U);
four_bar_named!(V);
#[allow(non_camel_case_types)]
mod self_ {
    four_bar_named!(Self_);
}

/// Parameters named like the generated code's temporaries and locals.
#[linkage::linkage(
    u = [theta3, theta4],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + s_theta3 * theta3.cos() + c_theta3 * theta4.cos() - psi,
        l2 * theta2.sin() + s_theta3 * theta3.sin() + c_theta3 * theta4.sin() + 0.0 * (inverse + rcond + det + gamma + psi_u + psi_v + udot + uddot + trig_u + trig_v + t0 + out),
    ],
)]
#[derive(Clone, Debug)]
#[allow(dead_code)] // some fields only take the generated code's names
pub struct Temporaries {
    pub psi: f64,
    pub l2: f64,
    pub s_theta3: f64,
    pub c_theta3: f64,
    pub inverse: f64,
    pub rcond: f64,
    pub det: f64,
    pub gamma: f64,
    pub psi_u: f64,
    pub psi_v: f64,
    pub udot: f64,
    pub uddot: f64,
    pub trig_u: f64,
    pub trig_v: f64,
    pub t0: f64,
    pub out: f64,
}

fn pose<L: Linkage<2, 1>>(model: &L) -> Analysis<2, 1, L::Points> {
    let guess = vector![70f64.to_radians(), -50f64.to_radians()];
    model
        .analyze(
            &guess,
            &vector![20f64.to_radians()],
            &vector![41.88790204786391],
            &vector![0.0],
            &Options::default(),
        )
        .expect("the worksheet's pose")
}

#[test]
fn structs_named_like_generated_parameters() {
    let reference = pose(&M::worksheet());
    // θ3 of the worksheet at θ2 = 20°.
    assert!((reference.u[0].to_degrees() - 70.55076547).abs() < 1e-8);
    for other in [
        pose(&F::worksheet()).u,
        pose(&N::worksheet()).u,
        pose(&D::worksheet()).u,
        pose(&U::worksheet()).u,
        pose(&V::worksheet()).u,
        pose(&self_::Self_::worksheet()).u,
    ] {
        assert_eq!(other, reference.u);
    }
    let k = M::worksheet().kinematics(
        &reference.u,
        &vector![20f64.to_radians()],
        &vector![1.0],
        &vector![0.0],
    );
    assert!(k.psi.amax() < 1e-12);
}

#[test]
fn fields_named_like_generated_temporaries() {
    let t = Temporaries {
        psi: 80.0,
        l2: 20.0,
        s_theta3: 50.0,
        c_theta3: 70.0,
        inverse: 1.0,
        rcond: 2.0,
        det: 3.0,
        gamma: 4.0,
        psi_u: 5.0,
        psi_v: 6.0,
        udot: 7.0,
        uddot: 8.0,
        trig_u: 9.0,
        trig_v: 10.0,
        t0: 11.0,
        out: 12.0,
    };
    let a = pose(&t);
    let b = pose(&M::worksheet());
    // The same equations under other names (0·x folds away in the DAG):
    // the same arithmetic, to the bit.
    assert_eq!((a.u, a.udot, a.uddot), (b.u, b.udot, b.uddot));
    let sweep = t
        .sweep(
            &a.u,
            &Drive::Line {
                from: vector![20f64.to_radians()],
                to: vector![80f64.to_radians()],
                steps: 60,
            },
            &SweepOptions::default(),
        )
        .expect("a regular sweep");
    assert!(sweep.complete);
}

/// The texts a user reads (the README, the docs, the sources, examples and
/// benchmarks with the tables they write) speak of the project's sources
/// by what they are, never by a tracker's issue numbers.
#[test]
fn no_user_visible_text_names_an_issue_number() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut found = Vec::new();
    let mut stack: Vec<std::path::PathBuf> = ["README.md", "docs", "src", "examples", "benches"]
        .iter()
        .map(|p| root.join(p))
        .collect();
    while let Some(path) = stack.pop() {
        if path.is_dir() {
            // Not a hidden folder: a reference script's own Python
            // environment (benches/reference/.venv) is not the project's text.
            let hidden = path
                .file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with('.'));
            if !hidden {
                for entry in std::fs::read_dir(&path).unwrap() {
                    stack.push(entry.unwrap().path());
                }
            }
            continue;
        }
        let text_file = ["md", "rs", "sh", "py", "csv", "toml"]
            .iter()
            .any(|e| path.extension().is_some_and(|x| x == *e));
        if !text_file {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for (n, line) in text.lines().enumerate() {
            let lower = line.to_lowercase();
            let mut rest = lower.as_str();
            while let Some(at) = rest.find("issue") {
                let after = rest[at + 5..].trim_start_matches([' ', '#']);
                if after.starts_with(|c: char| c.is_ascii_digit()) {
                    found.push(format!("{}:{}: {line}", path.display(), n + 1));
                }
                rest = &rest[at + 5..];
            }
        }
    }
    assert!(
        found.is_empty(),
        "issue numbers in user-visible text:\n{}",
        found.join("\n")
    );
}
