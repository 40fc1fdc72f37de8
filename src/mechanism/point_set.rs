//! The points of a run-time mechanism: up to `P` of them held inline, so
//! that they are `Copy` like a compiled mechanism's `[Vector2<f64>; n]`
//! and an analysis returns them without allocating.

use nalgebra::Vector2;

/// The positions (or velocities, or accelerations) of a run-time
/// mechanism's named points: the first `len` of `P` slots, in the order of
/// its point names. Reads as a slice (`as_ref()`), like a compiled
/// mechanism's array.
#[derive(Clone, Copy, Debug)]
pub struct PointSet<const P: usize> {
    len: usize,
    slots: [Vector2<f64>; P],
}

impl<const P: usize> PointSet<P> {
    /// `len` points at the origin; `None` if `len` exceeds the capacity `P`.
    pub fn zeros(len: usize) -> Option<PointSet<P>> {
        (len <= P).then(|| PointSet {
            len,
            slots: [Vector2::zeros(); P],
        })
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the mechanism has no named point.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl<const P: usize> AsRef<[Vector2<f64>]> for PointSet<P> {
    fn as_ref(&self) -> &[Vector2<f64>] {
        &self.slots[..self.len]
    }
}

impl<const P: usize> AsMut<[Vector2<f64>]> for PointSet<P> {
    fn as_mut(&mut self) -> &mut [Vector2<f64>] {
        &mut self.slots[..self.len]
    }
}

/// Equal when the points are: the unused slots do not count.
impl<const P: usize> PartialEq for PointSet<P> {
    fn eq(&self, other: &Self) -> bool {
        self.as_ref() == other.as_ref()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_points_count() {
        let mut a = PointSet::<4>::zeros(2).unwrap();
        let mut b = a;
        a.as_mut()[1] = Vector2::new(1.0, 2.0);
        assert_ne!(a, b);
        b.as_mut()[1] = Vector2::new(1.0, 2.0);
        assert_eq!(a, b);
        assert_eq!(a.as_ref().len(), 2);
        assert!(PointSet::<4>::zeros(5).is_none());
        assert!(PointSet::<4>::zeros(0).unwrap().is_empty());
    }
}
