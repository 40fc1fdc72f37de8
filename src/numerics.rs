//! The one-dimensional numerics the machine and the cam share: adaptive
//! Gauss–Kronrod quadrature, a bracketed root, Brent's minimisation, a
//! coarse scan refined by it, and the bisection of a yes/no question (the
//! smallest size at which a design works).

/// Gauss–Kronrod 7–15 nodes (the positive half) and weights, to the digits
/// of the published tables.
#[allow(clippy::excessive_precision)]
const XGK: [f64; 8] = [
    0.991_455_371_120_812_639_206_854_697_526_3,
    0.949_107_912_342_758_524_526_189_684_047_9,
    0.864_864_423_359_769_072_789_712_788_640_9,
    0.741_531_185_599_394_439_863_864_773_280_8,
    0.586_087_235_467_691_130_294_144_845_693_0,
    0.405_845_151_377_397_166_906_606_412_076_9,
    0.207_784_955_007_898_467_600_689_403_773_2,
    0.0,
];
#[allow(clippy::excessive_precision)]
const WGK: [f64; 8] = [
    0.022_935_322_010_529_224_963_732_008_058_97,
    0.063_092_092_629_978_553_290_700_663_189_20,
    0.104_790_010_322_250_183_839_876_322_541_5,
    0.140_653_259_715_525_918_745_189_590_510_2,
    0.169_004_726_639_267_902_826_583_426_598_6,
    0.190_350_578_064_785_409_913_256_402_421_0,
    0.204_432_940_075_298_892_414_161_999_234_6,
    0.209_482_141_084_727_828_012_999_174_891_7,
];
/// The Gauss 7-point weights, for the nodes XGK[1], XGK[3], XGK[5], XGK[7].
#[allow(clippy::excessive_precision)]
const WG: [f64; 4] = [
    0.129_484_966_168_869_693_270_611_432_679_1,
    0.279_705_391_489_276_667_901_467_771_423_8,
    0.381_830_050_505_118_944_950_369_775_489_0,
    0.417_959_183_673_469_387_755_102_040_816_3,
];

/// One Gauss–Kronrod 15-point rule on [a, b] of a vector-valued f, per
/// component: ∫ₐᵇ f, the error estimate |Kronrod − Gauss|, and ∫ₐᵇ |f|
/// (the scale of the rounding).
struct Rule {
    value: Vec<f64>,
    error: Vec<f64>,
    absolute: Vec<f64>,
}

fn kronrod<E>(f: &mut impl FnMut(f64) -> Result<Vec<f64>, E>, a: f64, b: f64) -> Result<Rule, E> {
    let (centre, half) = (0.5 * (a + b), 0.5 * (b - a));
    let fc = f(centre)?;
    let mut kronrod: Vec<f64> = fc.iter().map(|y| y * WGK[7]).collect();
    let mut gauss: Vec<f64> = fc.iter().map(|y| y * WG[3]).collect();
    let mut absolute: Vec<f64> = fc.iter().map(|y| y.abs() * WGK[7]).collect();
    for j in 0..7 {
        let dx = half * XGK[j];
        let (l, r) = (f(centre - dx)?, f(centre + dx)?);
        for i in 0..kronrod.len() {
            kronrod[i] += WGK[j] * (l[i] + r[i]);
            absolute[i] += WGK[j] * (l[i].abs() + r[i].abs());
            if j % 2 == 1 {
                gauss[i] += WG[j / 2] * (l[i] + r[i]);
            }
        }
    }
    Ok(Rule {
        error: kronrod
            .iter()
            .zip(&gauss)
            .map(|(k, g)| ((k - g) * half).abs())
            .collect(),
        value: kronrod.iter().map(|k| k * half).collect(),
        absolute: absolute.iter().map(|x| x * half.abs()).collect(),
    })
}

/// ∫ₐᵇ f of a vector-valued f by one 15-point rule, no error estimate
/// kept: for an integrand smooth on a short [a, b] (a grid cell between
/// kinks), where one rule is exact to rounding. (On the shaper's ∂M/∂p
/// over its half-degree cells (720 a turn), the adaptive [`integrate`]'s criterion applied
/// to each component gave the same bits on every component not zero to
/// rounding, at ten times the cost.)
pub(crate) fn integrate_cell<E>(
    f: &mut impl FnMut(f64) -> Result<Vec<f64>, E>,
    a: f64,
    b: f64,
) -> Result<Vec<f64>, E> {
    Ok(kronrod(f, a, b)?.value)
}

/// ∫ₐᵇ f, adaptively bisecting until each piece's estimated error is below
/// its share of `tolerance` (absolute). For an integrand smooth on [a, b]:
/// split at its kinks first.
pub(crate) fn integrate<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    tolerance: f64,
) -> Result<f64, E> {
    if a == b {
        return Ok(0.0);
    }
    let mut f = |x: f64| f(x).map(|y| vec![y]);
    let mut total = 0.0;
    // (a, b, depth); at most 2¹² pieces: beyond that the integrand is not
    // smooth where the caller says it is, and more pieces will not help.
    let mut stack = vec![(a, b, 0u32)];
    let length = (b - a).abs();
    while let Some((lo, hi, depth)) = stack.pop() {
        let rule = kronrod(&mut f, lo, hi)?;
        let share = tolerance * (hi - lo).abs() / length;
        // Below the rounding of the sum itself, an estimate means nothing.
        let noise = 50.0 * f64::EPSILON * rule.absolute[0];
        if rule.error[0] <= share.max(noise) || depth >= 12 {
            total += rule.value[0];
        } else {
            let mid = 0.5 * (lo + hi);
            stack.push((mid, hi, depth + 1));
            stack.push((lo, mid, depth + 1));
        }
    }
    Ok(total)
}

/// A root of g in [a, b], where g(a) and g(b) differ in sign, to the
/// precision of f64 (bisection safeguarding the secant: Illinois method).
pub(crate) fn root<E>(
    g: &mut impl FnMut(f64) -> Result<f64, E>,
    mut a: f64,
    mut b: f64,
) -> Result<f64, E> {
    let (mut ga, mut gb) = (g(a)?, g(b)?);
    if ga == 0.0 {
        return Ok(a);
    }
    if gb == 0.0 {
        return Ok(b);
    }
    let mut side = 0;
    for _ in 0..200 {
        let x = (a * gb - b * ga) / (gb - ga);
        let x = if x.is_finite() && x > a.min(b) && x < a.max(b) {
            x
        } else {
            0.5 * (a + b)
        };
        let gx = g(x)?;
        if gx == 0.0 || (b - a).abs() <= 4.0 * f64::EPSILON * x.abs().max(1.0) {
            return Ok(x);
        }
        if (gx > 0.0) == (gb > 0.0) {
            b = x;
            gb = gx;
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        } else {
            a = x;
            ga = gx;
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        }
    }
    Ok(0.5 * (a + b))
}

/// The minimum of f on [a, b] by Brent's method (golden section with
/// parabolic steps), to `tolerance` in x. Returns (x, f(x)).
pub(crate) fn minimize<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    tolerance: f64,
) -> Result<(f64, f64), E> {
    const GOLDEN: f64 = 0.381_966_011_250_105_1;
    let (mut a, mut b) = (a.min(b), a.max(b));
    let mut x = a + GOLDEN * (b - a);
    let (mut w, mut v) = (x, x);
    let mut fx = f(x)?;
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e): (f64, f64) = (0.0, 0.0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        let tol = tolerance + f64::EPSILON.sqrt() * 1e-4 * x.abs();
        let t2 = 2.0 * tol;
        if (x - m).abs() <= t2 - 0.5 * (b - a) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol {
            // A parabola through x, w, v.
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            let mut q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            if p.abs() < (0.5 * q * e).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < t2 || b - u < t2 {
                    d = if x < m { tol } else { -tol };
                }
                golden = false;
            }
        }
        if golden {
            e = if x < m { b - x } else { a - x };
            d = GOLDEN * e;
        }
        let u = if d.abs() >= tol {
            x + d
        } else if d > 0.0 {
            x + tol
        } else {
            x - tol
        };
        let fu = f(u)?;
        if fu <= fx {
            if u < x {
                b = x;
            } else {
                a = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Ok((x, fx))
}

/// `n` + 1 equally spaced samples of [a, b], `inset` in from each end.
pub(crate) fn samples(a: f64, b: f64, inset: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|i| a + inset + (b - a - 2.0 * inset) * i as f64 / n as f64)
        .collect()
}

/// The index of the least of `ys` (the first of equals; 0 if empty).
pub(crate) fn argmin(ys: &[f64]) -> usize {
    (0..ys.len())
        .min_by(|&p, &q| ys[p].total_cmp(&ys[q]))
        .unwrap_or(0)
}

/// The index of the greatest of `ys` (the last of equals; 0 if empty).
pub(crate) fn argmax(ys: &[f64]) -> usize {
    (0..ys.len())
        .max_by(|&p, &q| ys[p].total_cmp(&ys[q]))
        .unwrap_or(0)
}

/// Brent's minimum of f between the neighbours of the sample `xs[k]` (a
/// coarse scan's best): (x, f(x)).
pub(crate) fn refine<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    xs: &[f64],
    k: usize,
    tolerance: f64,
) -> Result<(f64, f64), E> {
    let (lo, hi) = (xs[k.saturating_sub(1)], xs[(k + 1).min(xs.len() - 1)]);
    minimize(f, lo, hi, tolerance)
}

/// A bracket [lo, hi] of the smallest size at which `feasible` holds: from
/// `hi`, widened by half at a time (lo taking the last infeasible one)
/// until feasible, up to `largest` — at most 200 widenings, and never past
/// the range of f64; `None` if none up to there is.
pub(crate) fn bracket_feasible(
    feasible: &mut impl FnMut(f64) -> bool,
    mut lo: f64,
    mut hi: f64,
    largest: f64,
) -> Option<(f64, f64)> {
    for _ in 0..200 {
        let within = hi <= largest && hi.is_finite(); // false for NaN too
        if !within {
            return None;
        }
        if feasible(hi) {
            return Some((lo, hi));
        }
        lo = hi;
        hi *= 1.5;
    }
    None
}

/// The smallest x in [lo, hi] at which `feasible` holds, by bisection (at
/// most 60 halvings, to 1e-13 relative), `hi` feasible.
pub(crate) fn bisect(feasible: &mut impl FnMut(f64) -> bool, mut lo: f64, mut hi: f64) -> f64 {
    if feasible(lo) {
        return lo;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if feasible(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-13 * hi {
            break;
        }
    }
    hi
}

#[cfg(test)]
mod tests {
    use super::*;

    type Never = std::convert::Infallible;

    #[test]
    fn quadrature_of_smooth_functions() {
        let mut f = |x: f64| Ok::<f64, Never>(x.cos());
        let v = integrate(&mut f, 0.0, 2.0, 1e-14).unwrap();
        assert!((v - 2f64.sin()).abs() < 1e-15);
        let mut g = |x: f64| Ok::<f64, Never>(1.0 / (1.0 + 25.0 * x * x));
        let v = integrate(&mut g, -1.0, 1.0, 1e-14).unwrap();
        assert!((v - 0.4 * 5f64.atan()).abs() < 1e-14);
    }

    /// One 15-point rule on a vector integrand: on a short interval exact
    /// to rounding, and its estimate says so; on a long one the estimate
    /// grows with the error.
    #[test]
    fn one_kronrod_rule_on_a_vector() {
        let mut f = |x: f64| Ok::<Vec<f64>, Never>(vec![x.cos(), x.exp(), 3.0 * x * x]);
        let rule = kronrod(&mut f, 0.2, 0.3).unwrap();
        let exact = [
            0.3f64.sin() - 0.2f64.sin(),
            0.3f64.exp() - 0.2f64.exp(),
            0.3f64.powi(3) - 0.2f64.powi(3),
        ];
        // (The exact differences round at the size of their terms, ≈ 1.)
        for (i, exact) in exact.iter().enumerate() {
            assert!(
                (rule.value[i] - exact).abs() <= 4.0 * f64::EPSILON,
                "{i}: {:?}",
                rule.value
            );
            assert!(rule.error[i] <= 1e-15);
        }
        let mut g = |x: f64| Ok::<Vec<f64>, Never>(vec![(20.0 * x).cos()]);
        let rule = kronrod(&mut g, 0.0, 10.0).unwrap();
        let error = (rule.value[0] - 200f64.sin() / 20.0).abs();
        assert!(
            error > 1e-3 && rule.error[0] > 0.1 * error,
            "{error} {}",
            rule.error[0]
        );
    }

    #[test]
    fn roots_and_minima() {
        let mut g = |x: f64| Ok::<f64, Never>(x.cos() - x);
        let r = root(&mut g, 0.0, 1.0).unwrap();
        assert!((r - 0.739_085_133_215_160_6).abs() < 1e-15);
        let mut f = |x: f64| Ok::<f64, Never>((x - 1.234).powi(2) + 0.5);
        let (x, fx) = minimize(&mut f, 0.0, 3.0, 1e-10).unwrap();
        assert!((x - 1.234).abs() < 1e-8 && (fx - 0.5).abs() < 1e-15);
    }

    #[test]
    fn bisection_finds_the_smallest_feasible_size() {
        let mut feasible = |x: f64| x >= 2.5;
        let (lo, hi) = bracket_feasible(&mut feasible, 0.0, 1.0, 100.0).unwrap();
        assert!(!feasible(lo) && feasible(hi));
        let x = bisect(&mut feasible, lo, hi);
        assert!(x >= 2.5 && x - 2.5 <= 1e-12);
        assert_eq!(bracket_feasible(&mut |_| false, 0.0, 1.0, 100.0), None);
        assert_eq!(argmin(&[2.0, 1.0, 1.0]), 1);
        assert_eq!(argmax(&[1.0, 2.0, 2.0]), 2);
    }
}
