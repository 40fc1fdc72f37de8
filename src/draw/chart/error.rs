//! What can go wrong drawing a chart, and the checks of its settings and
//! values.

/// What went wrong drawing a chart, motion diagrams or hodographs.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum DiagramError {
    /// A size or a number of columns is out of its range.
    BadSetting {
        what: &'static str,
        must: &'static str,
        value: f64,
    },
    /// The sweep has fewer than two poses.
    TooFewPoses { poses: usize },
    /// A value to plot is NaN, infinite, or beyond ±1e300 (where the
    /// axes' arithmetic would overflow).
    NonFinite {
        what: &'static str,
        name: String,
        pose: usize,
    },
    /// A value on a logarithmic axis is zero or negative.
    NotPositive {
        what: &'static str,
        name: String,
        pose: usize,
    },
}

crate::error::error_impls! {
    DiagramError {
        Self::BadSetting { what, must, value } => ("{what} must be {must}, got {value}"),
        Self::TooFewPoses { poses } => ("motion diagrams need a sweep of at least two poses, got {poses}"),
        Self::NonFinite { name, pose, what } => ("the {what} of `{name}` at pose {pose} is not finite, or beyond ±1e300"),
        Self::NotPositive { name, pose, what } => ("the {what} of `{name}` at pose {pose} is not positive, on a logarithmic axis"),
    }
    wraps {  }
}

/// Whether a value can be plotted: finite and within ±1e300, so that an
/// axis's span and its padding cannot overflow.
pub(crate) fn plottable(x: f64) -> bool {
    x.abs() <= 1e300 // false for NaN too
}

/// The first of `values` that cannot be plotted, as an error.
pub(crate) fn check_plottable(
    what: &'static str,
    name: &str,
    values: impl IntoIterator<Item = f64>,
    per_pose: usize,
) -> Result<(), DiagramError> {
    match values.into_iter().position(|x| !plottable(x)) {
        Some(i) => Err(DiagramError::NonFinite {
            what,
            name: name.into(),
            pose: i / per_pose.max(1),
        }),
        None => Ok(()),
    }
}

/// The largest side of a picture, in pixels.
pub(crate) const MAX_PIXELS: u32 = 20_000;

/// A size or a count, checked: in `range`.
pub(crate) fn within(
    what: &'static str,
    must: &'static str,
    value: u64,
    range: std::ops::RangeInclusive<u64>,
) -> Result<u32, DiagramError> {
    if range.contains(&value) {
        Ok(value as u32)
    } else {
        Err(DiagramError::BadSetting {
            what,
            must,
            value: value as f64,
        })
    }
}

/// A picture's width, checked: 200 to 20 000 pixels.
pub(crate) fn width(value: u32) -> Result<u32, DiagramError> {
    within(
        "the width",
        "from 200 to 20 000 pixels",
        value.into(),
        200..=MAX_PIXELS.into(),
    )
}

/// A panel's or a row's height, checked: `least` to 20 000 pixels.
pub(crate) fn height(value: u32, least: u32) -> Result<u32, DiagramError> {
    within(
        "a panel's height",
        "from 120 (160 for hodographs) to 20 000 pixels",
        value.into(),
        least.into()..=MAX_PIXELS.into(),
    )
}

/// Panels per row, and the rows they make of `panels`, checked: 1 to 20
/// columns, the whole picture at most 20 000 pixels high for `each` pixels
/// a row.
pub(crate) fn grid(columns: usize, panels: usize, each: u32) -> Result<(usize, u32), DiagramError> {
    let columns = within(
        "the number of columns",
        "from 1 to 20",
        columns as u64,
        1..=20,
    )? as usize;
    let rows = panels.div_ceil(columns).max(1);
    let tall = within(
        "the picture's height",
        "at most 20 000 pixels (rows × their height)",
        rows as u64 * u64::from(each),
        0..=MAX_PIXELS.into(),
    )?;
    Ok((rows, tall))
}
