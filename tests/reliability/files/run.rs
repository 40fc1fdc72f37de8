//! One case, run as a user would: the text built or the file read and
//! made into its mechanism, then — at the sizes compiled here — the
//! assembly at the drivers' pose, the analysis of that pose, a short sweep
//! over the drive, and the file's drawing. Every error is checked for a
//! place in the text (and rendered, as the tool renders it), every number
//! of an `Ok` for being finite.

use linkage::assembly::{Assemble, Mode, Pick};
use linkage::file::{Drives, MechanismFile};
use linkage::mechanism::{Diagnostic, Diagnostics, Fixed, Mechanism, MechanismError};
use linkage::prelude::*;

/// What a case came to.
#[derive(Default, Debug)]
pub(crate) struct Report {
    /// Where it ended: the first error's stage and kind, or how far the
    /// analyses went.
    pub(crate) kind: String,
    /// NaN or ∞ inside an `Ok`.
    pub(crate) lies: Vec<String>,
    /// Errors without a place in the text, or with one outside it.
    pub(crate) unlocated: Vec<String>,
    /// Errors that should not happen (`Internal`, a view refused at the
    /// mechanism's own sizes).
    pub(crate) internal: Vec<String>,
}

impl Report {
    fn lie(&mut self, what: &str, ok: bool) {
        if !ok {
            self.lies.push(format!("NaN or ∞ inside an Ok: {what}"));
        }
    }
}

/// The first word of a value's `Debug`: an error's variant.
fn variant(e: &dyn std::fmt::Debug) -> String {
    let text = format!("{e:?}");
    text.split(|c: char| !c.is_alphanumeric())
        .find(|s| !s.is_empty())
        .unwrap_or("?")
        .to_string()
}

/// Whether `range` is a place in `text`: inside it, on character
/// boundaries.
fn in_text(text: &str, range: &std::ops::Range<usize>) -> bool {
    range.start <= range.end
        && range.end <= text.len()
        && text.is_char_boundary(range.start)
        && text.is_char_boundary(range.end)
}

/// Diagnostics checked for their places (every one has one, in the text,
/// and so have its labels), rendered as the tool renders them. Names in
/// `outside` were given outside the text (a text's mechanism name and
/// parameters, arguments of `from_text`): a mistake about one of them has
/// no place in the text.
pub(crate) fn located(
    report: &mut Report,
    diagnostics: &Diagnostics,
    text: &str,
    outside: &[&str],
) {
    for d in diagnostics.iter() {
        let about_outside =
            || (outside.iter()).any(|name| d.message().contains(&format!("`{name}`")));
        match d.range() {
            Some(r) if in_text(text, &r) => {}
            None if about_outside() => {}
            other => report
                .unlocated
                .push(format!("{:?} at {other:?}", d.message())),
        }
        for label in d.labels() {
            if !in_text(text, &label.range()) {
                report.unlocated.push(format!(
                    "the label {:?} at {:?}",
                    label.message(),
                    label.range()
                ));
            }
        }
        if d.message().trim().is_empty() {
            report
                .unlocated
                .push("a diagnostic without a message".into());
        }
    }
    let rendered = diagnostics.render("fuzz.toml", text, false);
    if rendered.is_empty() {
        report
            .unlocated
            .push("diagnostics rendered as nothing".into());
    }
}

/// A mechanism that could not be made: its error checked and named.
fn refused(report: &mut Report, error: MechanismError, text: &str, outside: &[&str]) {
    let _ = error.to_string();
    match &error {
        MechanismError::Mistakes(d) => {
            located(report, d, text, outside);
            report.kind = format!("build: {}", mistake_kind(d));
        }
        MechanismError::Internal { what } => {
            report.internal.push(what.clone());
            report.kind = "build: Internal".into();
        }
        other => report.kind = format!("build: {}", variant(other)),
    }
}

/// A family of mistakes, by the first one's message.
fn mistake_kind(d: &Diagnostics) -> &'static str {
    let Some(first) = d.iter().next() else {
        return "no mistake";
    };
    family(first.message())
}

/// A family of mistakes, by its message.
pub(crate) fn family(message: &str) -> &'static str {
    let families: &[(&str, &str)] = &[
        ("TOML:", "TOML syntax"),
        ("defined twice", "TOML syntax"),
        ("the file is not UTF-8", "not UTF-8"),
        ("unknown unit", "unknown unit"),
        ("unit of", "unit of the wrong kind"),
        ("belongs here", "unit of the wrong kind"),
        ("moves ", "unit of the wrong kind"),
        ("must start with a number", "value not a number"),
        ("unknown key", "unknown key"),
        ("finite", "value not finite"),
        ("zero length", "zero-length range"),
        ("must be a whole number", "count out of range"),
        ("out of range", "count out of range"),
        ("steps must agree", "steps disagree"),
        ("the file has no", "missing key"),
        ("has no `", "missing key"),
        ("picks no assembly", "missing key"),
        ("missing", "missing key"),
        ("is required", "missing key"),
        ("must be", "wrong type"),
        ("escapes", "equations with escapes"),
        ("singular", "structurally singular"),
        ("in no equation", "structurally singular"),
        ("deep", "too large or deep"),
        ("too large", "too large or deep"),
        ("too many", "too large or deep"),
        ("bytes long", "too large or deep"),
        ("more than", "too large or deep"),
        ("unsupported", "unsupported form"),
        ("only unary", "unsupported form"),
        ("only numeric", "unsupported form"),
        ("only `", "unsupported form"),
        ("casts", "unsupported form"),
        ("mismatched", "syntax of the equations"),
        ("never closed", "syntax of the equations"),
        ("unclosed", "syntax of the equations"),
        ("expected", "syntax of the equations"),
        ("unexpected", "syntax of the equations"),
        ("is written `", "syntax of the equations"),
        ("takes a bracketed list", "syntax of the equations"),
        ("needs two coordinates", "syntax of the equations"),
        ("plain name", "syntax of the equations"),
        ("can only follow", "syntax of the equations"),
        ("has the coordinates", "syntax of the equations"),
        ("is a point; use", "syntax of the equations"),
        ("argument", "syntax of the equations"),
        ("invalid digit", "syntax of the equations"),
        ("cannot find", "unknown name"),
        ("unknown", "unknown name"),
        ("not a", "unknown name"),
        ("no parameter", "unknown name"),
        ("is not used", "unused name"),
        ("unused", "unused name"),
        ("twice", "name twice"),
        ("both", "name twice"),
        ("sketches", "name in the wrong place"),
        ("equations", "wrong counts"),
        ("identifier", "not an identifier"),
    ];
    for (needle, family) in families {
        if message.contains(needle) {
            return family;
        }
    }
    "other mistake"
}

/// The steps of the short sweeps: a few, whatever the file says.
const SHORT: usize = 24;
/// The sub-steps a step of the short sweeps may take (the default is
/// 100 000): a file's drive of 10⁵ turns is work a sweep does, at a few
/// microseconds a sub-step, not a fault; here it ends in `SubstepLimit`,
/// and every case's time is bounded by the work the library is asked for.
const SUBSTEPS: usize = 2_000;

fn vector<const N: usize>(xs: &[f64]) -> SVector<f64, N> {
    SVector::from_fn(|k, _| xs.get(k).copied().unwrap_or(0.0))
}

fn finite<'a>(xs: impl IntoIterator<Item = &'a f64>) -> bool {
    xs.into_iter().all(|x| x.is_finite())
}

fn finite_mode<const M: usize>(mode: &Mode<M>) -> bool {
    finite(&mode.u)
        && mode.points.iter().all(finite)
        && mode.rcond.is_finite()
        && mode.residual.is_finite()
}

fn finite_sweep<const M: usize, const F: usize>(sweep: &Sweep<M, F>) -> bool {
    sweep.poses.iter().all(|p| {
        finite(&p.v)
            && finite(&p.u)
            && finite(&p.vdot)
            && finite(&p.udot)
            && finite(&p.uddot)
            && p.det.is_finite()
            && p.rcond.is_finite()
    }) && sweep
        .events
        .iter()
        .all(|e| finite(&e.v) && finite(&e.u) && e.t.is_finite() && e.rank_measure.is_finite())
}

/// The analyses a user runs, at the mechanism's sizes: assembly at `at`,
/// the analysis there, the sweep back to `from` if `at` is elsewhere and
/// a short one over the range, and the picture.
fn analyses<const M: usize, const F: usize>(
    report: &mut Report,
    mechanism: &Mechanism,
    drives: &Drives,
    pick: Pick<M>,
    file: Option<&MechanismFile>,
) {
    let model: Fixed<M, F> = match mechanism.fixed::<M, F>() {
        Ok(model) => model,
        Err(e) => {
            report
                .internal
                .push(format!("the view at its own sizes: {e}"));
            report.kind = "view: refused".into();
            return;
        }
    };
    let at = vector::<F>(&drives.at);
    let mode = match model.assemble(&at, &pick) {
        Ok(mode) => mode,
        Err(e) => {
            let _ = e.to_string();
            report.kind = format!("assemble: {}", variant(&e));
            return;
        }
    };
    report.lie("the assembly", finite_mode(&mode));
    let pose = model.analyze(
        &mode.u,
        &at,
        &vector::<F>(&drives.rate),
        &vector::<F>(&drives.acceleration),
        &Options::default(),
    );
    let pose = match pose {
        Ok(pose) => pose,
        Err(e) => {
            let _ = e.to_string();
            report.kind = format!("analyze: {}", variant(&e));
            return;
        }
    };
    let points = |set: &<Fixed<M, F> as Kernels<M, F>>::Points| set.as_ref().iter().all(finite);
    report.lie(
        "the analysis",
        finite(&pose.u)
            && finite(&pose.udot)
            && finite(&pose.uddot)
            && finite(&pose.ratios)
            && points(&pose.points)
            && points(&pose.point_velocities)
            && points(&pose.point_accelerations)
            && pose.residual.is_finite()
            && pose.rcond.is_finite(),
    );
    let mut options = SweepOptions {
        max_substeps: SUBSTEPS,
        ..SweepOptions::default()
    };
    if F == 1 {
        options.speed = drives.rate[0];
    }
    let from = vector::<F>(&drives.from);
    let mut start = mode.u;
    if at != from {
        let back = Drive::Line {
            from: at,
            to: from,
            steps: SHORT,
        };
        match model.sweep(&mode.u, &back, &options) {
            Ok(carried) => {
                report.lie("the sweep back to `from`", finite_sweep(&carried));
                if !carried.complete {
                    report.kind = "sweep back: stopped at a limit position".into();
                    return;
                }
                start = carried.poses.last().map_or(mode.u, |p| p.u);
            }
            Err(e) => {
                let _ = e.to_string();
                report.kind = format!("sweep back: {}", variant(&e));
                return;
            }
        }
    }
    let drive = Drive::Line {
        from,
        to: vector::<F>(&drives.to),
        steps: drives.steps.clamp(1, SHORT),
    };
    let sweep = match model.sweep(&start, &drive, &options) {
        Ok(sweep) => sweep,
        Err(e) => {
            let _ = e.to_string();
            report.kind = format!("sweep: {}", variant(&e));
            return;
        }
    };
    report.lie("the sweep", finite_sweep(&sweep));
    report.kind = if sweep.complete {
        "Ok: the whole sweep".into()
    } else {
        "Ok: the sweep stopped at a limit position".into()
    };
    #[cfg(feature = "draw")]
    if let Some(file) = file {
        use linkage::draw::scene::Frame;
        let frame = Frame::from_analysis(&model, &pose);
        let cycle: Vec<Frame> = (sweep.poses.iter())
            .map(|p| Frame::from_sweep_pose(&model, p))
            .collect();
        match file.scene().render(&frame, &cycle) {
            Ok(svg) => {
                if let Err(why) = clean_svg(&svg, file) {
                    report.lies.push(format!("the drawing: {why}"));
                }
            }
            Err(e) => {
                let _ = e.to_string();
                report.kind = format!("draw: {}", variant(&e));
            }
        }
    }
    #[cfg(not(feature = "draw"))]
    let _ = file;
}

/// An SVG that is XML, with no NaN or ∞ in its numbers (attributes, and
/// the text it writes that is not a name or title from the file).
#[cfg(feature = "draw")]
fn clean_svg(svg: &str, file: &MechanismFile) -> Result<(), String> {
    let document = roxmltree::Document::parse(svg).map_err(|e| format!("not XML: {e}"))?;
    let bad = |s: &str| {
        s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-' || c == '+'))
            .any(|w| {
                let w = w.trim_start_matches(['-', '+']);
                w == "NaN" || w == "inf" || w == "infinity"
            })
    };
    let mut own: Vec<String> = file.title.iter().cloned().collect();
    if let Some(drawing) = &file.drawing {
        own.extend(drawing.ground.iter().map(|(n, _)| n.text.clone()));
    }
    own.push(file.name.text.clone());
    for node in document.descendants() {
        for a in node.attributes() {
            let name = a.name();
            if name == "id" || name == "class" || name == "href" || name.starts_with("data-") {
                continue;
            }
            if bad(a.value()) {
                return Err(format!("{name}=\"{}\"", a.value()));
            }
        }
        if let Some(text) = node.text().filter(|_| node.is_text()) {
            let named = own
                .iter()
                .any(|n| !n.is_empty() && text.contains(n.as_str()))
                || text
                    .chars()
                    .all(|c| c.is_alphanumeric() || c == '_' || c.is_whitespace());
            if !named && bad(text) {
                return Err(format!("the text {text:?}"));
            }
        }
    }
    Ok(())
}

/// A pick of `M` coordinates, from a choice made for any size.
trait AnyPick {
    fn at<const M: usize>(&self) -> Option<Pick<M>>;
}

/// Runs the analyses at the mechanism's sizes.
fn at_sizes<P: AnyPick>(
    report: &mut Report,
    mechanism: &Mechanism,
    drives: &Drives,
    pick: &P,
    file: Option<&MechanismFile>,
) {
    // The choice at the size, or (a mistake in it, kept by the choice)
    // nothing to run.
    macro_rules! sized {
        ($($m:literal, $f:literal);*) => {
            match (mechanism.m(), mechanism.f()) {
                $(($m, $f) => match pick.at::<$m>() {
                    Some(p) => analyses::<$m, $f>(report, mechanism, drives, p, file),
                    None => {}
                },)*
                (m, f) => report.kind = format!("sizes: m = {m}, f = {f}, not compiled here"),
            }
        };
    }
    sized!(1, 1; 2, 1; 3, 1; 4, 1; 5, 1; 6, 1; 7, 1; 8, 1; 10, 1; 1, 2; 2, 2; 3, 2);
}

/// The first assembly, whatever the size.
struct First;

impl AnyPick for First {
    fn at<const M: usize>(&self) -> Option<Pick<M>> {
        Some(Pick::Index(0))
    }
}

/// A case of mechanism texts: the text, its name and parameters, and the
/// drive to analyse it at.
pub(crate) struct TextCase {
    pub(crate) name: String,
    pub(crate) text: String,
    pub(crate) parameters: Vec<(String, f64)>,
    /// v at the pose, and where a short sweep goes from there.
    pub(crate) at: Vec<f64>,
    pub(crate) to: Vec<f64>,
}

pub(crate) fn text_case(case: &TextCase) -> Report {
    let mut report = Report::default();
    let parameters: Vec<(&str, f64)> = (case.parameters.iter())
        .map(|(n, x)| (n.as_str(), *x))
        .collect();
    let mechanism = match Mechanism::from_text(&case.name, &case.text, &parameters) {
        Ok(m) => m,
        Err(e) => {
            let mut outside: Vec<&str> = parameters.iter().map(|(n, _)| *n).collect();
            outside.push(&case.name);
            refused(&mut report, e, &case.text, &outside);
            return report;
        }
    };
    let _ = mechanism.methods_agree();
    let drives = Drives {
        at: case.at.clone(),
        from: case.at.clone(),
        to: case.to.clone(),
        rate: vec![1.0; 3],
        acceleration: vec![0.0; 3],
        steps: SHORT,
    };
    at_sizes(&mut report, &mechanism, &drives, &First, None);
    report
}

/// The file's assembly choice, at a size.
struct FileChoice<'a> {
    file: &'a MechanismFile,
    u_names: Vec<&'static str>,
    mistake: std::cell::RefCell<Option<Diagnostic>>,
}

impl AnyPick for FileChoice<'_> {
    fn at<const M: usize>(&self) -> Option<Pick<M>> {
        match &self.file.assembly {
            None => Some(Pick::Index(0)),
            Some(choice) => match choice.pick::<M>(&self.u_names) {
                Ok(pick) => Some(pick),
                Err(mistake) => {
                    *self.mistake.borrow_mut() = Some(mistake);
                    None
                }
            },
        }
    }
}

/// A case of mechanism files: the file's text.
pub(crate) fn file_case(text: &str) -> Report {
    let mut report = Report::default();
    let file = match MechanismFile::parse(text) {
        Ok(file) => file,
        Err(errors) => {
            let _ = errors.to_string();
            for e in &errors.errors {
                let _ = e.line_col(text);
            }
            let diagnostics = Diagnostics::from(&errors);
            located(&mut report, &diagnostics, text, &[]);
            if errors.errors.is_empty() {
                report
                    .unlocated
                    .push("a file refused without a mistake".into());
            }
            report.kind = format!("file: {}", mistake_kind(&diagnostics));
            return report;
        }
    };
    let mechanism = match file.mechanism() {
        Ok(m) => m,
        Err(e) => {
            refused(&mut report, e, text, &[]);
            return report;
        }
    };
    let _ = mechanism.methods_agree();
    // A driving coordinate without its table: a mistake at the file's
    // name, as the tool reports it.
    let drives = match file.drives(mechanism.v_names()) {
        Ok(drives) => drives,
        Err(missing) => {
            located(&mut report, &missing, text, &[]);
            report.kind = "drive: a driver without its table".into();
            return report;
        }
    };
    let choice = FileChoice {
        file: &file,
        u_names: mechanism.u_names().to_vec(),
        mistake: Default::default(),
    };
    at_sizes(&mut report, &mechanism, &drives, &choice, Some(&file));
    if let Some(mistake) = choice.mistake.into_inner() {
        let mut d = Diagnostics::new();
        d.push(mistake);
        located(&mut report, &d, text, &[]);
        report.kind = "assembly: a sketch that is not the mechanism's".into();
    }
    report
}
