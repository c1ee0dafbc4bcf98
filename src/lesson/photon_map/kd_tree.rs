//! The structure the slide "Photon Mapping" asks for: one that finds the k nearest neighbours of any 3D
//! point fast. A k-d tree: the points are split at the median of the axis along which they spread most,
//! each half split again, down to single points; a search descends to the point's own side first and visits
//! the other side of a split only when the plane is nearer than the k-th nearest point found so far.
//!
//! The tree is kept in one array: the median of a range stands in its middle, the smaller half before it,
//! the larger after it, and each split's axis is stored beside it.

use crate::lesson::math::Vector;
use std::collections::BinaryHeap;

/// A k-d tree over points, each with the index it was given.
#[derive(Clone, Debug, Default)]
pub struct KdTree {
    /// The points, ordered so that each range's median stands in its middle.
    points: Vec<(Vector, u32)>,
    /// The axis (0, 1, 2) each range was split along, stored at its median.
    axes: Vec<u8>,
}

/// A point found, ordered by its squared distance, then its index (so that equal distances are settled the
/// same way every time).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Found(f32, u32);

impl Eq for Found {}

impl Ord for Found {
    fn cmp(&self, other: &Found) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

impl PartialOrd for Found {
    fn partial_cmp(&self, other: &Found) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl KdTree {
    /// The tree over `points` (non-finite ones are left out), each found by its index in the list.
    pub fn new(points: impl IntoIterator<Item = Vector>) -> KdTree {
        let mut points: Vec<(Vector, u32)> =
            points.into_iter().enumerate().filter(|(_, p)| p.is_finite()).map(|(i, p)| (p, i as u32)).collect();
        let mut axes = vec![0; points.len()];
        split(&mut points, &mut axes);
        KdTree { points, axes }
    }

    /// The indices of the (at most) `k` points nearest to `p` within the squared distance `max_d2`, with
    /// their squared distances.
    pub fn nearest(&self, p: Vector, k: usize, max_d2: f32) -> Vec<(f32, u32)> {
        let mut heap = BinaryHeap::with_capacity(k + 1);
        self.search(0, self.points.len(), p, k, max_d2, &mut heap);
        heap.into_iter().map(|Found(d2, i)| (d2, i)).collect()
    }

    fn search(&self, lo: usize, hi: usize, p: Vector, k: usize, max_d2: f32, heap: &mut BinaryHeap<Found>) {
        if lo >= hi || k == 0 {
            return;
        }
        let mid = (lo + hi) / 2;
        let (point, index) = self.points[mid];
        let d2 = point.distance_squared(p);
        if d2 <= max_d2 {
            heap.push(Found(d2, index));
            if heap.len() > k {
                heap.pop();
            }
        }
        let axis = self.axes[mid] as usize;
        let across = p[axis] - point[axis];
        let (near, far) = if across < 0.0 { ((lo, mid), (mid + 1, hi)) } else { ((mid + 1, hi), (lo, mid)) };
        self.search(near.0, near.1, p, k, max_d2, heap);
        let reach = if heap.len() < k { max_d2 } else { heap.peek().map_or(max_d2, |f| f.0) };
        if across * across <= reach {
            self.search(far.0, far.1, p, k, max_d2, heap);
        }
    }
}

/// Orders `points` so that the median along the axis of largest spread stands in the middle, and does the
/// same on each side.
fn split(points: &mut [(Vector, u32)], axes: &mut [u8]) {
    if points.len() <= 1 {
        return;
    }
    let (min, max) =
        points.iter().fold((Vector::INFINITY, Vector::NEG_INFINITY), |(lo, hi), (p, _)| (lo.min(*p), hi.max(*p)));
    let spread = max - min;
    let axis = if spread.x >= spread.y && spread.x >= spread.z {
        0
    } else if spread.y >= spread.z {
        1
    } else {
        2
    };
    let mid = points.len() / 2;
    points.select_nth_unstable_by(mid, |a, b| a.0[axis].total_cmp(&b.0[axis]).then(a.1.cmp(&b.1)));
    axes[mid] = axis as u8;
    let (left, right) = points.split_at_mut(mid);
    let (left_axes, right_axes) = axes.split_at_mut(mid);
    split(left, left_axes);
    split(&mut right[1..], &mut right_axes[1..]);
}
