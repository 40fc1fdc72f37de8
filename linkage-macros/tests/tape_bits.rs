//! The tapes give the compiled code's numbers to the bit. Each mechanism
//! below is compiled by the attribute and, from the same text, built at run
//! time through the pipeline (parse, lower, differentiate, emit) and
//! compiled into tapes; every kernel of both is evaluated at random inputs
//! and every entry compared by its bits (NaN to any NaN: the sign and
//! payload of a NaN are not a value, and LLVM does not keep them). The
//! tapes on several lanes give each lane's single-lane bits.

// The derivative of `2.0.powf(x)` has the literal ln 2 in the generated
// code, which clippy takes for an approximate `LN_2`.
#![allow(clippy::approx_constant)]

use linkage::SensitivityKernel;
use linkage::nalgebra::{SMatrix, SVector, Vector2};
use linkage_symbolic::ast::Input as Attribute;
use linkage_symbolic::errors::Errors;
use linkage_symbolic::plan::{Formula, Kernel};
use linkage_symbolic::tape::{Input, Part, Tape, Tapes};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// A part of a compiled result, dense, row by row.
struct Dense {
    rows: usize,
    cols: usize,
    values: Vec<f64>,
}

fn matrix<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> Dense {
    Dense {
        rows: R,
        cols: C,
        values: (0..R)
            .flat_map(|i| (0..C).map(move |j| m[(i, j)]))
            .collect(),
    }
}

/// One (x, y) per point.
fn points<const N: usize>(p: &[Vector2<f64>; N]) -> Dense {
    Dense {
        rows: N,
        cols: 2,
        values: p.iter().flat_map(|v| [v.x, v.y]).collect(),
    }
}

/// Columns of one (x, y) per point: row 2i + c, column j.
fn point_columns<const N: usize, const C: usize>(p: &[[Vector2<f64>; N]; C]) -> Dense {
    Dense {
        rows: 2 * N,
        cols: C,
        values: (0..2 * N)
            .flat_map(|r| (0..C).map(move |j| p[j][r / 2][r % 2]))
            .collect(),
    }
}

fn same_bits(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

/// The outputs of a phase against the compiled parts: each output the
/// entry its part lists, every other entry zero.
fn compare(
    what: &str,
    parts: &[Part],
    out: &[f64],
    compiled: &[Dense],
) -> Result<(), TestCaseError> {
    prop_assert_eq!(parts.len(), compiled.len(), "{}: parts", what);
    let mut outputs = out.iter();
    for (part, dense) in parts.iter().zip(compiled) {
        prop_assert_eq!((part.rows, part.cols), (dense.rows, dense.cols));
        let mut listed = vec![false; dense.values.len()];
        for &(i, j) in &part.entries {
            let k = i * dense.cols + j;
            listed[k] = true;
            let tape = outputs.next().copied().unwrap_or(f64::NAN);
            let compiled = dense.values[k];
            prop_assert!(
                same_bits(tape, compiled),
                "{}: {}[({}, {})] is {:e} ({:#x}) on the tape, {:e} ({:#x}) compiled",
                what,
                part.name,
                i,
                j,
                tape,
                tape.to_bits(),
                compiled,
                compiled.to_bits()
            );
        }
        for (k, listed) in listed.iter().enumerate() {
            if !listed {
                prop_assert!(
                    dense.values[k] == 0.0,
                    "{}: {} entry {}",
                    what,
                    part.name,
                    k
                );
            }
        }
    }
    prop_assert!(outputs.next().is_none(), "{}: outputs left over", what);
    Ok(())
}

/// Random inputs of a mechanism.
#[derive(Clone, Debug)]
struct Sample {
    u: Vec<f64>,
    v: Vec<f64>,
    udot: Vec<f64>,
    vdot: Vec<f64>,
    uddot: Vec<f64>,
    vddot: Vec<f64>,
    fields: Vec<f64>,
}

impl Sample {
    /// The sines and cosines the kernels with them given read: of the
    /// coordinates shifted, so that a kernel computing them instead gives
    /// other numbers.
    fn sin_cos(x: f64) -> (f64, f64) {
        (x + 0.25).sin_cos()
    }

    fn trig(q: &[f64]) -> Vec<f64> {
        q.iter()
            .flat_map(|&x| {
                let (s, c) = Sample::sin_cos(x);
                [s, c]
            })
            .collect()
    }

    /// Every input of `tape`, on one lane of `registers`.
    fn write<const L: usize>(
        &self,
        registers: &mut linkage_symbolic::tape::Registers<L>,
        lane: usize,
    ) {
        let inputs = [
            (Input::U, self.u.clone()),
            (Input::V, self.v.clone()),
            (Input::Udot, self.udot.clone()),
            (Input::Vdot, self.vdot.clone()),
            (Input::Uddot, self.uddot.clone()),
            (Input::Vddot, self.vddot.clone()),
            (Input::TrigU, Sample::trig(&self.u)),
            (Input::TrigV, Sample::trig(&self.v)),
            (Input::Fields, self.fields.clone()),
        ];
        for (input, values) in inputs {
            registers
                .set_lane(input, lane, &values)
                .expect("inputs of the tape's sizes");
        }
    }
}

/// Numbers over a wide range, mostly of moderate size.
fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -4.0..4.0_f64,
        1 => -1e3..1e3_f64,
        1 => -1e-3..1e-3_f64,
    ]
}

fn sample(m: usize, f: usize, fields: usize) -> impl Strategy<Value = Sample> {
    let v = |n: usize| proptest::collection::vec(number(), n);
    (
        (v(m), v(f), v(m), v(f), v(m), v(f)),
        proptest::collection::vec(0.2..3.0_f64, fields),
    )
        .prop_map(|((u, v, udot, vdot, uddot, vddot), fields)| Sample {
            u,
            v,
            udot,
            vdot,
            uddot,
            vddot,
            fields,
        })
}

/// 64 cases, and no file of failures written beside the test.
fn config() -> ProptestConfig {
    let mut config = ProptestConfig::with_cases(64);
    config.failure_persistence = None;
    config
}

/// The tapes of a mechanism's text, built at run time.
fn tapes(attr: &str, item: &str) -> Tapes {
    let attr: proc_macro2::TokenStream = attr.parse().expect("the attribute's text");
    let item: proc_macro2::TokenStream = item.parse().expect("the struct's text");
    let mut errors = Errors::default();
    let input = Attribute::parse(attr, item, &mut errors).expect("a struct");
    let model = match linkage_symbolic::build(&input, &mut errors) {
        Ok(model) => model,
        Err(_) => panic!("the attribute has mistakes: {:?}", errors.combined()),
    };
    Tapes::build(&model).expect("every kernel compiles")
}

/// Every phase of a tape on L lanes at once against each lane alone.
fn run_lanes_against_single<const L: usize>(
    tape: &Tape,
    samples: &[Sample],
) -> Result<(), TestCaseError> {
    let mut lanes = tape.registers::<L>();
    let mut singles: Vec<_> = samples.iter().map(|_| tape.registers::<1>()).collect();
    for (l, s) in samples.iter().enumerate() {
        s.write(&mut lanes, l);
        s.write(&mut singles[l], 0);
    }
    for phase in 0..tape.phases() {
        let mut out = vec![[0.0; L]; tape.outputs(phase)];
        tape.run_lanes(phase, &mut lanes, &mut out)
            .expect("a call that fits");
        for (l, registers) in singles.iter_mut().enumerate() {
            let mut one = vec![0.0; tape.outputs(phase)];
            tape.run(phase, registers, &mut one)
                .expect("a call that fits");
            for (k, (lanes, single)) in out.iter().zip(&one).enumerate() {
                prop_assert!(
                    same_bits(lanes[l], *single),
                    "phase {} output {} lane {}: {} on {} lanes, {} alone",
                    phase,
                    k,
                    l,
                    lanes[l],
                    L,
                    single
                );
            }
        }
    }
    Ok(())
}

/// A mechanism compiled by the attribute, with its text for the run-time
/// pipeline and a property test comparing them.
macro_rules! mechanism {
    (
        $module:ident, $name:ident { $($field:ident),* $(,)? },
        m = $m:literal, f = $f:literal, k = $k:literal, points = $np:literal,
        [$($attr:tt)*]
    ) => {
        mod $module {
            use super::*;

            #[linkage::linkage($($attr)*)]
            #[derive(Clone, Debug)]
            pub struct $name {
                $(pub $field: f64),*
            }

            const ATTR: &str = stringify!($($attr)*);
            const ITEM: &str = stringify!(pub struct $name { $(pub $field: f64),* });
            const FIELDS: usize = [$(stringify!($field)),*].len();

            fn vector<const N: usize>(x: &[f64]) -> SVector<f64, N> {
                SVector::from_iterator(x.iter().copied())
            }

            fn pairs<const N: usize>(x: &[f64]) -> [(f64, f64); N] {
                std::array::from_fn(|k| Sample::sin_cos(x[k]))
            }

            /// The compiled kernel's result, part by part (one phase).
            fn compiled(mech: &$name, kernel: Kernel, s: &Sample) -> Vec<Dense> {
                let (u, v) = (vector::<$m>(&s.u), vector::<$f>(&s.v));
                let (udot, vdot) = (vector::<$m>(&s.udot), vector::<$f>(&s.vdot));
                let (uddot, vddot) = (vector::<$m>(&s.uddot), vector::<$f>(&s.vddot));
                let (trig_u, trig_v) = (pairs::<$m>(&s.u), pairs::<$f>(&s.v));
                match kernel {
                    Kernel::Formula(Formula::Psi) => vec![matrix(&mech.psi(&u, &v))],
                    Kernel::Formula(Formula::PsiQ) => vec![matrix(&mech.psi_q(&u, &v))],
                    Kernel::Formula(Formula::PsiU) => vec![matrix(&mech.psi_u(&u, &v))],
                    Kernel::Formula(Formula::PsiV) => vec![matrix(&mech.psi_v(&u, &v))],
                    Kernel::PsiAndPsiU => {
                        let (psi, psi_u) = mech.psi_and_psi_u(&u, &v);
                        vec![matrix(&psi), matrix(&psi_u)]
                    }
                    Kernel::Formula(Formula::PsiUUdotU) => {
                        vec![matrix(&mech.psi_u_udot_u(&u, &v, &udot))]
                    }
                    Kernel::Formula(Formula::PsiUUdotV) => {
                        vec![matrix(&mech.psi_u_udot_v(&u, &v, &udot))]
                    }
                    Kernel::Formula(Formula::PsiVVdotU) => {
                        vec![matrix(&mech.psi_v_vdot_u(&u, &v, &vdot))]
                    }
                    Kernel::Formula(Formula::PsiVVdotV) => {
                        vec![matrix(&mech.psi_v_vdot_v(&u, &v, &vdot))]
                    }
                    Kernel::Formula(Formula::PsiUDot) => {
                        vec![matrix(&mech.psi_u_dot(&u, &v, &udot, &vdot))]
                    }
                    Kernel::Formula(Formula::PsiVDot) => {
                        vec![matrix(&mech.psi_v_dot(&u, &v, &udot, &vdot))]
                    }
                    Kernel::Formula(Formula::Gamma) => {
                        vec![matrix(&mech.gamma(&u, &v, &udot, &vdot))]
                    }
                    Kernel::Formula(Formula::PsiP) => vec![matrix(&mech.psi_p(&u, &v))],
                    Kernel::Points(0) => vec![points(&mech.point_positions(&u, &v))],
                    Kernel::Points(1) => {
                        vec![points(&mech.point_velocities(&u, &v, &udot, &vdot))]
                    }
                    Kernel::Points(_) => vec![points(&mech.point_accelerations(&u, &v, &udot, &vdot, &uddot, &vddot))],
                    Kernel::SensitivityTerms { with_trig } => {
                        let t = if with_trig {
                            mech.sensitivity_terms_with_trig(
                                &u, &v, &trig_u, &trig_v, &udot, &vdot, &uddot, &vddot,
                            )
                        } else {
                            mech.sensitivity_terms(&u, &v, &udot, &vdot, &uddot, &vddot)
                        };
                        vec![
                            matrix(&t.psi_u),
                            matrix(&t.psi_p),
                            matrix(&t.psi_u_dot),
                            matrix(&t.psi_p_dot),
                            matrix(&t.psi_u_ddot),
                            matrix(&t.psi_p_ddot),
                            point_columns(&t.points_u),
                            point_columns(&t.points_p),
                            point_columns(&t.point_velocities_u),
                            point_columns(&t.point_velocities_p),
                            point_columns(&t.point_accelerations_u),
                            point_columns(&t.point_accelerations_p),
                        ]
                    }
                    // A run-time mechanism's own: the compiled mechanism's
                    // three levels of the points.
                    Kernel::PointMotion => vec![
                        points(&mech.point_positions(&u, &v)),
                        points(&mech.point_velocities(&u, &v, &udot, &vdot)),
                        points(&mech.point_accelerations(&u, &v, &udot, &vdot, &uddot, &vddot)),
                    ],
                    // A run-time mechanism's own: the compiled mechanism's
                    // position terms, read from its whole terms.
                    Kernel::PositionSensitivityTerms => {
                        let t = mech.position_terms_with_trig(&u, &v, &trig_u, &trig_v);
                        vec![
                            matrix(&t.psi_u),
                            matrix(&t.psi_p),
                            point_columns(&t.points_u),
                            point_columns(&t.points_p),
                        ]
                    }
                    Kernel::Kinematics { .. } | Kernel::Formula(_) => Vec::new(),
                }
            }

            /// The two phases of `kinematics` against the compiled one: Ψ,
            /// Ψ_u, Ψ_v, then γ at the compiled u̇, which gives the compiled
            /// ü through the same solve.
            fn kinematics(
                mech: &$name,
                tape: &Tape,
                with_trig: bool,
                s: &Sample,
            ) -> Result<(), TestCaseError> {
                let (u, v) = (vector::<$m>(&s.u), vector::<$f>(&s.v));
                let (vdot, vddot) = (vector::<$f>(&s.vdot), vector::<$f>(&s.vddot));
                let k = if with_trig {
                    let (trig_u, trig_v) = (pairs::<$m>(&s.u), pairs::<$f>(&s.v));
                    mech.kinematics_with_trig(&u, &v, &trig_u, &trig_v, &vdot, &vddot)
                } else {
                    mech.kinematics(&u, &v, &vdot, &vddot)
                };
                let mut registers = tape.registers::<1>();
                s.write(&mut registers, 0);
                let mut first = vec![0.0; tape.outputs(0)];
                tape.run(0, &mut registers, &mut first).expect("a call that fits");
                let compiled = [matrix(&k.psi), matrix(&k.psi_u), matrix(&k.psi_v)];
                compare("kinematics, phase 0", tape.parts(0), &first, &compiled)?;
                registers
                    .set(Input::Udot, k.udot.as_slice())
                    .expect("u̇ of m entries");
                let mut second = vec![0.0; tape.outputs(1)];
                tape.run(1, &mut registers, &mut second).expect("a call that fits");
                let mut gamma = SVector::<f64, $m>::zeros();
                for (&(i, _), &value) in tape.parts(1)[0].entries.iter().zip(&second) {
                    gamma[i] = value;
                }
                let uddot = -k.factors.solve(&(k.psi_v * vddot + gamma));
                for i in 0..$m {
                    prop_assert!(
                        same_bits(uddot[i], k.uddot[i]),
                        "kinematics, ü[{}]: {} through the tape's γ, {} compiled",
                        i,
                        uddot[i],
                        k.uddot[i]
                    );
                }
                Ok(())
            }

            /// The masks of the kernels with the sines and cosines given.
            #[test]
            fn the_trig_masks_are_the_compiled_ones() {
                let tapes = tapes(ATTR, ITEM);
                let mask = |tape: &Tape, range: std::ops::Range<usize>| -> Vec<bool> {
                    range.map(|k| tape.trig_coords().contains(&k)).collect()
                };
                let kinematics = tapes.get(Kernel::Kinematics { with_trig: true });
                assert_eq!(mask(kinematics, 0..$m), $name::TRIG_U.to_vec());
                assert_eq!(mask(kinematics, $m..$m + $f), $name::TRIG_V.to_vec());
                let terms = tapes.get(Kernel::SensitivityTerms { with_trig: true });
                assert_eq!(mask(terms, 0..$m), $name::SENSITIVITY_TRIG_U.to_vec());
                assert_eq!(mask(terms, $m..$m + $f), $name::SENSITIVITY_TRIG_V.to_vec());
                assert_eq!($name::PARAM_NAMES.len(), $k);
                assert_eq!($name::POINT_NAMES.len(), $np);
            }

            /// Every kernel at these inputs, one lane at a time and on four
            /// lanes at once.
            pub fn check(samples: &[Sample]) -> Result<(), TestCaseError> {
                thread_local! {
                    static TAPES: Tapes = tapes(ATTR, ITEM);
                }
                TAPES.with(|tapes| {
                    for s in samples {
                        let mut fields = s.fields.iter().copied();
                        let mech = $name {
                            $($field: fields.next().unwrap_or(1.0)),*
                        };
                        for kernel in Kernel::every() {
                            let tape = tapes.get(kernel);
                            if let Kernel::Kinematics { with_trig } = kernel {
                                kinematics(&mech, tape, with_trig, s)?;
                                continue;
                            }
                            let mut registers = tape.registers::<1>();
                            s.write(&mut registers, 0);
                            if kernel == Kernel::PointMotion {
                                // The pose's own sines and cosines, as an
                                // analysis gives them: the compiled points
                                // compute theirs.
                                let exact = |q: &[f64]| -> Vec<f64> {
                                    q.iter().flat_map(|&x| <[f64; 2]>::from(x.sin_cos())).collect()
                                };
                                for (input, q) in [(Input::TrigU, &s.u), (Input::TrigV, &s.v)] {
                                    registers.set_lane(input, 0, &exact(q)).expect("inputs of the tape's sizes");
                                }
                            }
                            let mut out = vec![0.0; tape.outputs(0)];
                            tape.run(0, &mut registers, &mut out).expect("a call that fits");
                            let compiled = compiled(&mech, kernel, s);
                            compare(kernel.name(), tape.parts(0), &out, &compiled)?;
                        }
                    }
                    for kernel in Kernel::every() {
                        run_lanes_against_single::<4>(tapes.get(kernel), samples)?;
                    }
                    Ok(())
                })
            }

            proptest! {
                #![proptest_config(config())]

                #[test]
                fn every_kernel_gives_the_compiled_bits(
                    samples in proptest::collection::vec(sample($m, $f, FIELDS), 4),
                ) {
                    check(&samples)?;
                }
            }
        }
    };
}

mechanism!(
    fourbar,
    FourBar { l1, l2, l3, l4 },
    m = 2,
    f = 1,
    k = 4,
    points = 5,
    [
        u = [theta3, theta4],
        v = [theta2],
        points = [
            B = (l2 * theta2.cos(), l2 * theta2.sin()),
            C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
            G2 = (0.5 * B.x, 0.5 * B.y),
            G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
            G4 = (C.x + 0.5 * l4 * theta4.cos(), C.y + 0.5 * l4 * theta4.sin()),
        ],
        closure = [
            l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
            l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        ],
    ]
);

// The slider-crank with its rod's slider position by the square root, and
// integer powers up to the fifth and negative ones.
mechanism!(
    slider_crank,
    SliderCrank { r, l, e },
    m = 2,
    f = 1,
    k = 3,
    points = 4,
    [
        u = [theta3, s],
        v = [theta2],
        points = [
            B = (r * theta2.cos(), r * theta2.sin()),
            P = (s, e),
            Q = (
                (l.powi(2) - (r * theta2.sin() - e).powi(2)).sqrt(),
                s.powi(5) / l.powi(3)
            ),
            R = (theta3.powi(-2) * r, (s * s + e * e).sqrt() * theta3.powi(7)),
        ],
        closure = [
            r * theta2.cos() + l * theta3.cos() - s,
            r * theta2.sin() + l * theta3.sin() - e + 0.01 * s.powi(3),
        ],
    ]
);

mechanism!(
    six_bar,
    SixBar {
        l1,
        l2,
        l3,
        l4,
        e,
        beta,
        l5,
        l6,
        gx,
        gy
    },
    m = 4,
    f = 1,
    k = 10,
    points = 4,
    [
        u = [theta3, theta4, theta5, theta6],
        v = [theta2],
        points = [
            B = (l2 * theta2.cos(), l2 * theta2.sin()),
            C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
            E = (
                B.x + e * (theta3 + beta).cos(),
                B.y + e * (theta3 + beta).sin()
            ),
            F = (E.x + l5 * theta5.cos(), E.y + l5 * theta5.sin()),
        ],
        closure = [
            l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
            l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
            E.x + l5 * theta5.cos() - gx - l6 * theta6.cos(),
            E.y + l5 * theta5.sin() - gy - l6 * theta6.sin(),
        ],
    ]
);

// Every function an equation may call, named constants, a point used in
// another, literal receivers (`2.0.powf(x)`, which LLVM turns into
// `exp2`), `powf` by one half (which LLVM turns into a square root),
// functions of constants (which LLVM folds: `powi` as `pow`) and a subset
// of the fields as parameters.
mechanism!(
    functions,
    Functions {
        l1,
        l2,
        l3,
        l4,
        a,
        b
    },
    m = 2,
    f = 1,
    k = 3,
    points = 5,
    [
        u = [theta3, theta4],
        v = [theta2],
        params = [l2, l3, a],
        points = [
            P = (
                l2 * theta2.cos() + PI * a,
                l3.hypot(theta3) + theta4.tan() * b
            ),
            Q = (
                P.x.abs() + (theta3 * 0.1).exp() + FRAC_PI_4,
                (P.y * P.y + 1.0).powf(1.5) + theta3.powf(0.5) + l1.powf(theta3),
            ),
            R = (
                2.0.powf(theta2) + powf(10.0, theta4 * 0.1) + atan2(1.0, theta3),
                Q.x.atan2(Q.y) * E + (a * theta4).sinh() + (b * theta3).cosh(),
            ),
            S = (
                (theta3 * 0.25).tanh() + (0.3 * theta4.sin()).asin() + (0.2 * theta2.cos()).acos(),
                (theta4 * theta4 + 1.0).ln()
                    + theta3.atan()
                    + std::f64::consts::SQRT_2 * (P.x - R.y),
            ),
            T = (
                SQRT_2.powi(5) * theta3 + FRAC_1_PI.powi(8) + LN_2.powi(9) * a,
                powf(2.0, PI) * theta4 + TAU.exp() * 0.001 + FRAC_PI_3.sin() * theta2,
            ),
        ],
        closure = [
            l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1
                + 0.01 * (a * theta3).atan2(l2)
                + 0.02 * (theta4 * theta4 + l1).sqrt(),
            l2 * theta2.sin()
                + l3 * theta3.sin()
                + l4 * theta4.sin()
                + 0.1 * (l3.hypot(theta4)).ln()
                + 0.01 * (b * theta3).exp() * theta4.abs(),
        ],
    ]
);

mechanism!(
    five_bar,
    FiveBar { l1, l2, l3, l4, l5 },
    m = 2,
    f = 2,
    k = 5,
    points = 3,
    [
        u = [theta3, theta4],
        v = [theta2, theta5],
        points = [
            B = (l2 * theta2.cos(), l2 * theta2.sin()),
            D = (l1 + l5 * theta5.cos(), l5 * theta5.sin()),
            C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        ],
        closure = [
            B.x + l3 * theta3.cos() - D.x - l4 * theta4.cos(),
            B.y + l3 * theta3.sin() - D.y - l4 * theta4.sin(),
        ],
    ]
);

/// The inputs at which glibc's `pow` differs from what optimised code
/// computes instead: `pow(2, x)` from `exp2(x)` at this θ2, `pow(x, 0.5)`
/// from `√x` at this θ3 (found by search; random inputs rarely hit
/// them). The tapes compute what the compiled code computes.
#[test]
fn the_powers_llvm_rewrites_give_the_compiled_bits() {
    let (two, half) = (std::hint::black_box(2.0_f64), std::hint::black_box(0.5));
    let (theta2, theta3) = (std::hint::black_box(THETA2), std::hint::black_box(THETA3));
    assert_ne!(two.powf(theta2), theta2.exp2());
    assert_ne!(theta3.powf(half), theta3.sqrt());
    let sample = Sample {
        u: vec![THETA3, 0.4],
        v: vec![THETA2],
        udot: vec![0.3, -0.2],
        vdot: vec![1.0],
        uddot: vec![0.1, 0.2],
        vddot: vec![-0.5],
        fields: vec![2.0, 1.0, 1.5, 1.8, 0.3, 0.7],
    };
    if let Err(e) = functions::check(&[sample]) {
        panic!("{e}");
    }
}

const THETA2: f64 = 1.8057575888408515;
const THETA3: f64 = 1.7916718046615017;
