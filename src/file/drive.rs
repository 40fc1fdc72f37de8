//! The drive: for each coordinate of v, the range a sweep runs over, its
//! number of poses, its rate and acceleration, and the pose to analyse.

use super::names::Name;
use super::quantity::{Accept, Quantity};
use super::reader::{Reader, Value};
use super::units::{Kind, Unit};

/// The steps of a sweep when the file does not say: one per degree of a
/// turn.
pub const DEFAULT_STEPS: usize = 360;
/// The most steps a sweep may ask for.
pub const MOST_STEPS: usize = 1_000_000;
/// The rate when the file does not say: 1 (rad/s or m/s), with which a
/// sweep's velocities and accelerations are the kinematic coefficients
/// du/dv and d²u/dv², as with `SweepOptions::default()`.
pub const DEFAULT_RATE: f64 = 1.0;

/// One driving coordinate: `[drive.<name>]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Driver {
    /// The coordinate of v (where the table's name is written).
    pub name: Name,
    /// Where a sweep starts.
    pub from: Quantity,
    /// Where a sweep ends.
    pub to: Quantity,
    /// The equal steps of a sweep from `from` to `to` (as
    /// `Drive::Line`: steps + 1 poses, both ends included): the file's,
    /// or [`DEFAULT_STEPS`]. The drivers of one file move together and
    /// share it.
    pub steps: usize,
    /// Where `steps` is written, if it is.
    pub steps_span: Option<std::ops::Range<usize>>,
    /// v̇: the file's, or [`DEFAULT_RATE`].
    pub rate: Quantity,
    /// v̈: the file's, or 0.
    pub acceleration: Quantity,
    /// The pose one analysis takes: the file's, or `from`.
    pub at: Quantity,
}

/// Whether a kind moves an angle or a length (a plain number says
/// neither).
fn family(kind: Kind) -> Option<&'static str> {
    match kind {
        Kind::Angle | Kind::AngularRate | Kind::AngularAcceleration => Some("an angle"),
        Kind::Length | Kind::LinearRate | Kind::LinearAcceleration => Some("a length"),
        _ => None,
    }
}

impl Reader<'_> {
    /// The `[drive]` table: one table per coordinate of v.
    pub(super) fn drive(&mut self, value: &Value<'_>, length: Unit) -> Vec<Driver> {
        let expected = "a table of drivers, one [drive.<name>] per coordinate of v";
        let Some(table) = self.table("drive", expected, value) else {
            return Vec::new();
        };
        let entries = table.all();
        if entries.is_empty() {
            self.error(
                table.span(),
                "`drive` has no driver: write a [drive.<name>] table with `from` and `to` for each coordinate of v",
            );
        }
        let mut drivers = Vec::new();
        for (key, span, value) in entries {
            let name = self.identifier(key, span);
            if let Some(driver) = self.driver(&table.place(key), name, value, length) {
                drivers.push(driver);
            }
        }
        self.shared_steps(&mut drivers);
        drivers
    }

    /// One driver's table (`name` is `None` if it is no name the
    /// equations can use: the table is still checked).
    fn driver(
        &mut self,
        path: &str,
        name: Option<Name>,
        value: &Value<'_>,
        length: Unit,
    ) -> Option<Driver> {
        let mut table = self.table(path, "a table with `from` and `to`", value)?;
        let range = "the sweep's range";
        let from = table.require(self, "from", range);
        let to = table.require(self, "to", range);
        let steps = table.take("steps");
        let rate = table.take("rate");
        let acceleration = table.take("acceleration");
        let at = table.take("at");
        let place = |key| table.place(key);
        let from = from.and_then(|v| self.quantity(&place("from"), v, Accept::COORDINATE, length));
        let to = to.and_then(|v| self.quantity(&place("to"), v, Accept::COORDINATE, length));
        let at = match at {
            Some(v) => self
                .quantity(&place("at"), v, Accept::COORDINATE, length)
                .map(Some),
            None => Some(None),
        };
        let steps_span = steps.map(|v| v.span());
        let steps = match steps {
            Some(v) => self.count(&place("steps"), v, 1, MOST_STEPS as u64),
            None => Some(DEFAULT_STEPS),
        };
        let rate = match rate {
            Some(v) => self.quantity(&place("rate"), v, Accept::RATE, length),
            None => Some(Quantity::default_of(DEFAULT_RATE)),
        };
        let acceleration = match acceleration {
            Some(v) => self.quantity(&place("acceleration"), v, Accept::ACCELERATION, length),
            None => Some(Quantity::default_of(0.0)),
        };
        table.finish(self);
        let (from, to, at, steps, rate, acceleration) =
            (from?, to?, at?, steps?, rate?, acceleration?);
        let at = at.unwrap_or_else(|| Quantity {
            span: None,
            ..from.clone()
        });
        self.one_family(path, [&from, &to, &at, &rate, &acceleration])?;
        if from.value == to.value {
            let message = format!(
                "the range of `{path}` has zero length: `from` and `to` are both {}",
                from.value
            );
            let error = self
                .mistake(to.span.clone().unwrap_or_default(), message)
                .label(from.span.clone().unwrap_or_default(), "`from`");
            self.push(error);
            return None;
        }
        Some(Driver {
            name: name?,
            from,
            to,
            steps,
            steps_span,
            rate,
            acceleration,
            at,
        })
    }

    /// A driver moves an angle or a length: its range, pose, rate and
    /// acceleration must agree on which (a plain number goes with either).
    fn one_family(&mut self, path: &str, quantities: [&Quantity; 5]) -> Option<()> {
        let mut first: Option<&Quantity> = None;
        for q in quantities {
            let Some(family_q) = family(q.kind) else {
                continue;
            };
            match first {
                None => first = Some(q),
                Some(f) if family(f.kind) == Some(family_q) => {}
                Some(f) => {
                    let message = format!(
                        "`{path}` moves {} (`{}`), but this is {} (`{}`)",
                        family(f.kind).unwrap_or_default(),
                        f.unit.as_deref().unwrap_or_default(),
                        q.kind,
                        q.unit.as_deref().unwrap_or_default(),
                    );
                    let error = self
                        .mistake(q.span.clone().unwrap_or_default(), message)
                        .label(f.span.clone().unwrap_or_default(), "the first unit written");
                    self.push(error);
                    return None;
                }
            }
        }
        Some(())
    }

    /// The drivers move together in a sweep: the steps written must agree,
    /// and a driver that does not write them takes the others'.
    fn shared_steps(&mut self, drivers: &mut [Driver]) {
        let Some(first) = drivers.iter().find(|d| d.steps_span.is_some()).cloned() else {
            return;
        };
        for driver in drivers.iter_mut() {
            match &driver.steps_span {
                Some(span) if driver.steps != first.steps => {
                    let message = format!(
                        "the drivers move together in a sweep, so their steps must agree: `{}` has {}, `{}` {}",
                        first.name.text, first.steps, driver.name.text, driver.steps
                    );
                    let error = self.mistake(span.clone(), message).label(
                        first.steps_span.clone().unwrap_or_default(),
                        "the first steps written",
                    );
                    self.push(error);
                }
                Some(_) => {}
                None => driver.steps = first.steps,
            }
        }
    }
}
