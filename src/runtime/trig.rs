//! Sines and cosines carried from pose to pose by the angle-addition
//! formulas, instead of computed.

use nalgebra::SVector;

/// The sines and cosines of the coordinates a model reads from its caller
/// ([`Kernels::kinematics_with_trig`](crate::runtime::Kernels::kinematics_with_trig)), carried from an anchor angle a by
/// the angle-addition formulas
///
/// ```text
/// sin(a + δ) = sin a + (sin a·(cos δ − 1) + cos a·sin δ)
/// cos(a + δ) = cos a + (cos a·(cos δ − 1) − sin a·sin δ)
/// ```
///
/// with sin δ and cos δ − 1 from their Taylor series: to δ⁵ for
/// |δ| ≤ 2⁻⁹, to δ⁹ for |δ| ≤ 1/16 (the truncation is below 10⁻¹⁸ either
/// way), `sin_cos` beyond. The correction is small against the anchor's
/// value, so the result is rounded about once: as accurate as a direct
/// `sin_cos`, for a handful of multiplications. Once a coordinate has moved
/// 2⁻¹⁰ from its anchor it is re-anchored where it is, the `sin_cos` of the
/// new anchor running beside the current step (the current value still
/// comes from the old anchor), so a dense sweep stays on the short series.
pub(crate) struct TrigCarrier<const M: usize, const F: usize> {
    anchor_u: [f64; M],
    trig_u: [(f64, f64); M],
    anchor_v: [f64; F],
    trig_v: [(f64, f64); F],
}

/// (sin, cos) of n angles.
pub(crate) type SinCos<const N: usize> = [(f64, f64); N];

/// The sines and cosines an analysis computed at its pose, handed on to the
/// sensitivities there ([`crate::runtime::Sensitivities::sensitivities_of`]): `sin_cos_u[k]` =
/// `u[k].sin_cos()` for the coordinates of [`crate::runtime::Kernels::trig_u`], and
/// likewise of the analysis's drivers v (the other entries unspecified).
/// They are used only at exactly this `u`: the analysis's own `u` may be
/// changed by its caller, its drivers may not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PoseTrig<const M: usize, const F: usize> {
    pub(crate) u: SVector<f64, M>,
    pub(crate) sin_cos_u: [(f64, f64); M],
    pub(crate) sin_cos_v: [(f64, f64); F],
}

impl<const M: usize, const F: usize> PoseTrig<M, F> {
    /// The sines and cosines the analysis computed at its pose (those of
    /// the coordinates `had`, its kernel's masks), completed with those of
    /// the coordinates another kernel reads (`flags`) and the analysis's
    /// did not (a point's angle, say), computed here: each exactly
    /// `sin_cos` of its coordinate at `u` and `v`, the pose's.
    #[inline(always)]
    pub(crate) fn completed(
        &self,
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
        (flags_u, flags_v): ([bool; M], [bool; F]),
        (had_u, had_v): ([bool; M], [bool; F]),
    ) -> (SinCos<M>, SinCos<F>) {
        let (mut trig_u, mut trig_v) = (self.sin_cos_u, self.sin_cos_v);
        for k in 0..M {
            if flags_u[k] && !had_u[k] {
                trig_u[k] = u[k].sin_cos();
            }
        }
        for k in 0..F {
            if flags_v[k] && !had_v[k] {
                trig_v[k] = v[k].sin_cos();
            }
        }
        (trig_u, trig_v)
    }
}

/// The ranges of |δ| carried by the short and the long series.
const SHORT_RANGE: f64 = 1.0 / 512.0;
const LONG_RANGE: f64 = 1.0 / 16.0;

impl<const M: usize, const F: usize> TrigCarrier<M, F> {
    /// Anchored nowhere: the first use anchors each coordinate it needs.
    pub(crate) fn new() -> Self {
        TrigCarrier {
            anchor_u: [f64::NAN; M],
            trig_u: [(0.0, 1.0); M],
            anchor_v: [f64::NAN; F],
            trig_v: [(0.0, 1.0); F],
        }
    }

    /// (sin, cos) of the masked coordinates of u and v (unspecified
    /// elsewhere).
    #[inline(always)]
    pub(crate) fn at(
        &mut self,
        mask_u: &[bool; M],
        mask_v: &[bool; F],
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
    ) -> (SinCos<M>, SinCos<F>) {
        (
            carry_all(mask_u, &mut self.anchor_u, &mut self.trig_u, u.as_slice()),
            carry_all(mask_v, &mut self.anchor_v, &mut self.trig_v, v.as_slice()),
        )
    }

    /// (sin, cos) at the anchors: right after [`TrigCarrier::exactly_at`],
    /// those of the u it was given, exactly, and of v wherever v was
    /// anchored (where it is, for a carrier that has seen one v only, as
    /// in a Newton solve).
    #[inline(always)]
    pub(crate) fn anchored(&self) -> (SinCos<M>, SinCos<F>) {
        (self.trig_u, self.trig_v)
    }

    /// [`TrigCarrier::at`] with the masked coordinates of u anchored where
    /// they are: their `sin_cos` exactly, bit for bit what the generated
    /// code computes itself (v is carried; it is exact where v has not
    /// moved from its anchor).
    #[inline(always)]
    pub(crate) fn exactly_at(
        &mut self,
        mask_u: &[bool; M],
        mask_v: &[bool; F],
        u: &SVector<f64, M>,
        v: &SVector<f64, F>,
    ) -> (SinCos<M>, SinCos<F>) {
        for k in 0..M {
            if mask_u[k] {
                self.anchor_u[k] = u[k];
                self.trig_u[k] = u[k].sin_cos();
            }
        }
        (
            self.trig_u,
            carry_all(mask_v, &mut self.anchor_v, &mut self.trig_v, v.as_slice()),
        )
    }
}

/// Whether carrying the sines and cosines from the pose `from` to `to`
/// pays: every masked coordinate moved within the short series' range, as
/// in a dense sweep. Beyond it a direct `sin_cos` costs less than the carry
/// and its re-anchoring (docs/performance.md, "Measurements behind the
/// code").
#[inline]
pub(crate) fn carry_pays<const N: usize>(
    mask: &[bool; N],
    from: &SVector<f64, N>,
    to: &SVector<f64, N>,
) -> bool {
    (0..N).all(|k| !mask[k] || (to[k] - from[k]).abs() <= SHORT_RANGE)
}

/// [`carry`] for every masked x[k]. The common case, every one within half
/// the short range of its anchor, is done lane by lane without branches
/// (all lanes, masked or not: the others' values are not read).
#[inline(always)]
fn carry_all<const N: usize>(
    mask: &[bool; N],
    anchor: &mut [f64; N],
    trig: &mut SinCos<N>,
    x: &[f64],
) -> SinCos<N> {
    let mut d = [0.0; N];
    let mut near = true;
    for k in 0..N {
        d[k] = x[k] - anchor[k];
        near &= !mask[k] | (d[k].abs() <= 0.5 * SHORT_RANGE);
    }
    let mut out = [(0.0, 1.0); N];
    if near {
        for k in 0..N {
            let d2 = d[k] * d[k];
            let sin_d = d[k] + d[k] * d2 * (SIN_1 + d2 * SIN_2);
            let cos_d_minus_1 = d2 * (COS_1 + d2 * COS_2);
            let (s, c) = trig[k];
            out[k] = (
                s + (s * cos_d_minus_1 + c * sin_d),
                c + (c * cos_d_minus_1 - s * sin_d),
            );
        }
    } else {
        for k in 0..N {
            if mask[k] {
                out[k] = carry(&mut anchor[k], &mut trig[k], x[k]);
            }
        }
    }
    out
}

/// The Taylor coefficients of sin δ − δ and cos δ − 1.
const SIN_1: f64 = -1.0 / 6.0;
const SIN_2: f64 = 1.0 / 120.0;
const SIN_3: f64 = -1.0 / 5040.0;
const SIN_4: f64 = 1.0 / 362_880.0;
const COS_1: f64 = -0.5;
const COS_2: f64 = 1.0 / 24.0;
const COS_3: f64 = -1.0 / 720.0;
const COS_4: f64 = 1.0 / 40_320.0;

/// (sin x, cos x) carried from the anchor (see [`TrigCarrier`]).
#[inline(always)]
fn carry(anchor: &mut f64, trig: &mut (f64, f64), x: f64) -> (f64, f64) {
    let d = x - *anchor;
    let distance = d.abs();
    // NaN (no anchor yet, or x not finite) takes the last branch.
    let (sin_d, cos_d_minus_1) = if distance <= SHORT_RANGE {
        let d2 = d * d;
        // sin δ = δ − δ³/3! + δ⁵/5!,  cos δ − 1 = −δ²/2! + δ⁴/4!
        (d + d * d2 * (SIN_1 + d2 * SIN_2), d2 * (COS_1 + d2 * COS_2))
    } else if distance <= LONG_RANGE {
        let d2 = d * d;
        // … to δ⁹ and δ⁸
        (
            d + d * d2 * (SIN_1 + d2 * (SIN_2 + d2 * (SIN_3 + d2 * SIN_4))),
            d2 * (COS_1 + d2 * (COS_2 + d2 * (COS_3 + d2 * COS_4))),
        )
    } else {
        return reanchor(anchor, trig, x);
    };
    let (s, c) = *trig;
    let carried = (
        s + (s * cos_d_minus_1 + c * sin_d),
        c + (c * cos_d_minus_1 - s * sin_d),
    );
    if distance > 0.5 * SHORT_RANGE {
        reanchor(anchor, trig, x);
    }
    carried
}

/// Anchors at x. Out of line, so that the compiler does not compute the
/// `sin_cos` at every call to turn the rare branch into a select.
#[cold]
#[inline(never)]
fn reanchor(anchor: &mut f64, trig: &mut (f64, f64), x: f64) -> (f64, f64) {
    *anchor = x;
    *trig = x.sin_cos();
    *trig
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Carried sines and cosines agree with `sin_cos` to about an ulp on
    /// every tier: the short series, the long one, and re-anchoring.
    #[test]
    fn carried_trig_is_as_accurate_as_sin_cos() {
        let mut worst: f64 = 0.0;
        for &step in &[1e-7_f64, 6.2e-6, 3e-4, 1.5e-3, 0.01, 0.05, 0.3] {
            let (mut anchor, mut trig) = (f64::NAN, (0.0, 1.0));
            let mut x = -2.9_f64;
            for _ in 0..(6.2_f64 / step).min(200_000.0) as usize {
                let (s, c) = carry(&mut anchor, &mut trig, x);
                let (es, ec) = x.sin_cos();
                worst = worst.max((s - es).abs()).max((c - ec).abs());
                x += step;
            }
        }
        // Two coordinates at once, one of them not read.
        for &step in &[6.2e-6_f64, 1e-3, 0.04] {
            let (mut anchor, mut trig) = ([f64::NAN; 2], [(0.0, 1.0); 2]);
            let mut x = [-2.9_f64, 7.0];
            for _ in 0..(6.2 / step).min(200_000.0) as usize {
                let out = carry_all(&[true, false], &mut anchor, &mut trig, &x);
                let (es, ec) = x[0].sin_cos();
                worst = worst.max((out[0].0 - es).abs()).max((out[0].1 - ec).abs());
                x[0] += step;
                x[1] += 1.0;
            }
            assert!(
                anchor[1].is_nan(),
                "the coordinate not read is never anchored"
            );
        }
        eprintln!("worst absolute error of the carried sin and cos: {worst:e}");
        assert!(worst <= 2.5e-16, "worst absolute error {worst:e}");
    }
}
