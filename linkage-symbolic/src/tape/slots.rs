//! Where a tape reads its inputs: the first registers of the register
//! file, one slot per entry of each argument of the generated function.

use std::ops::Range;

/// An argument of a generated function, as a tape reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Input {
    /// The dependent coordinates u (m).
    U,
    /// The driving coordinates v (f).
    V,
    /// u̇ (m); in `kinematics`, written by the caller between the phases.
    Udot,
    /// v̇ (f).
    Vdot,
    /// ü (m).
    Uddot,
    /// v̈ (f).
    Vddot,
    /// (sin uₖ, cos uₖ) of each coordinate of u, in pairs (2m).
    TrigU,
    /// (sin vₖ, cos vₖ) of each coordinate of v, in pairs (2f).
    TrigV,
    /// The struct's `f64` fields in the order declared, every one of
    /// them (`self.l1, self.l2, …`), not only the parameters p.
    Fields,
}

impl Input {
    /// Every input, in the order of their slots.
    pub const ALL: [Input; 9] = [
        Input::U,
        Input::V,
        Input::Udot,
        Input::Vdot,
        Input::Uddot,
        Input::Vddot,
        Input::TrigU,
        Input::TrigV,
        Input::Fields,
    ];
}

/// The sizes of a mechanism that lay out the input slots.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Slots {
    /// Dependent coordinates.
    pub m: usize,
    /// Driving coordinates.
    pub f: usize,
    /// `f64` fields of the struct.
    pub fields: usize,
}

impl Slots {
    /// How many values an input has.
    #[inline]
    pub fn len(self, input: Input) -> usize {
        match input {
            Input::U | Input::Udot | Input::Uddot => self.m,
            Input::V | Input::Vdot | Input::Vddot => self.f,
            Input::TrigU => 2 * self.m,
            Input::TrigV => 2 * self.f,
            Input::Fields => self.fields,
        }
    }

    /// The registers of an input: after those of the inputs before it in
    /// [`Input::ALL`] (u, v, u̇, v̇, ü, v̈: m + f each; then 2m, 2f).
    #[inline]
    pub fn range(self, input: Input) -> Range<usize> {
        let (m, f) = (self.m, self.f);
        let start = match input {
            Input::U => 0,
            Input::V => m,
            Input::Udot => m + f,
            Input::Vdot => 2 * m + f,
            Input::Uddot => 2 * (m + f),
            Input::Vddot => 3 * m + 2 * f,
            Input::TrigU => 3 * (m + f),
            Input::TrigV => 5 * m + 3 * f,
            Input::Fields => 5 * (m + f),
        };
        start..start + self.len(input)
    }

    /// How many registers the inputs take.
    pub fn total(self) -> usize {
        Input::ALL.iter().map(|&i| self.len(i)).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each input's registers follow those of the inputs before it.
    #[test]
    fn the_ranges_lay_the_inputs_end_to_end() {
        let slots = Slots {
            m: 3,
            f: 2,
            fields: 4,
        };
        let mut next = 0;
        for input in Input::ALL {
            let range = slots.range(input);
            assert_eq!(
                (range.start, range.len()),
                (next, slots.len(input)),
                "{input:?}"
            );
            next = range.end;
        }
        assert_eq!(next, slots.total());
    }
}
