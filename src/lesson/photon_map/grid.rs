//! The photon map's search structure (slide "Photon Mapping": fast k-nearest-neighbour search): a uniform
//! grid of cubic cells, the photons sorted cell by cell (see the module documentation of
//! [`crate::lesson::photon_map`]).

use crate::lesson::geometry::Aabb;
use crate::lesson::math::{Vector, floor};

/// The radii, as fractions of the maximum radius, of the balls an estimate searches for its k nearest
/// photons, smallest first (the last is the maximum radius itself): where the caustic is dense, the k
/// nearest lie in the smallest ball and the larger ones are never read.
pub(super) const SEARCH_FRACTIONS: [f32; 3] = [0.25, 0.5, 1.0];

/// A photon an estimate found: its squared distance from the point and its index, in one integer ordered
/// by the distance first and by the index among photons at the same distance (the order of a non-negative
/// float's bits is that of its values), so that choosing the k nearest compares integers and is the same
/// every time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct Found(u64);

impl Found {
    fn new(d2: f32, index: u32) -> Found {
        debug_assert!(d2 >= 0.0);
        Found(((d2.to_bits() as u64) << 32) | index as u64)
    }
    pub(super) fn d2(self) -> f32 {
        f32::from_bits((self.0 >> 32) as u32)
    }
    pub(super) fn index(self) -> usize {
        self.0 as u32 as usize
    }
}

/// The photons sorted into a uniform grid of cubic cells, [`CELLS_PER_RADIUS`] to `max_radius` (or fewer,
/// see [`CELLS_PER_PHOTON`]; see the module documentation). Cell (x, y, z) is number `x + nx * (y + ny * z)`, so a row of cells along x is one run.
pub(super) struct PhotonGrid {
    origin: Vector,
    /// The cells' width, and one over it.
    cell: f32,
    inv_cell: f32,
    dims: [usize; 3],
    /// The photons of cell c are `entries[starts[c] .. starts[c + 1]]`.
    starts: Vec<u32>,
    /// Each photon's position and index, cell by cell (in index order within a cell).
    entries: Vec<([f32; 3], u32)>,
}

/// At most this many cells per photon: a radius small against the photons' spread widens the cells
/// instead of allocating an empty grid of millions of cells.
const CELLS_PER_PHOTON: f32 = 2.0;

/// Cells across the maximum radius: the smallest ball an estimate searches (see [`SEARCH_FRACTIONS`]) is
/// then a cell wide, and larger balls read few photons outside them.
pub(super) const CELLS_PER_RADIUS: f32 = 4.0;

impl PhotonGrid {
    /// The grid over `photons`, each where `position` says, for estimates within `max_radius`.
    pub(super) fn new<P>(photons: &[P], position: impl Fn(&P) -> Vector, max_radius: f32) -> PhotonGrid {
        let bounds = Aabb::from_points(photons.iter().map(&position));
        let extent = if photons.is_empty() { Vector::ZERO } else { bounds.max - bounds.min };
        let max_cells = (CELLS_PER_PHOTON * photons.len() as f32).max(1.0);
        // A zero radius finds only photons at the point itself, with cells of any width.
        let mut cell = if max_radius > 0.0 { max_radius / CELLS_PER_RADIUS } else { f32::MIN_POSITIVE };
        let dims = loop {
            // At most `max_cells` along an axis before the cast, so that no count overflows.
            let dims = [0, 1, 2].map(|k| (extent[k] / cell).min(max_cells) as usize + 1);
            let cells = dims.iter().map(|&d| d as f32).product::<f32>();
            if cells <= max_cells {
                break dims;
            }
            cell *= (cells / max_cells).cbrt().max(1.0 + f32::EPSILON.sqrt());
        };
        let origin = if photons.is_empty() { Vector::ZERO } else { bounds.min };
        let mut grid = PhotonGrid { origin, cell, inv_cell: 1.0 / cell, dims, starts: Vec::new(), entries: Vec::new() };
        // A counting sort of the photons by cell.
        let cell_of: Vec<usize> = photons
            .iter()
            .map(|p| {
                let [x, y, z] = grid.coords(position(p)).map(|c| c.clamp(0, i64::MAX) as usize);
                grid.index(x.min(dims[0] - 1), y.min(dims[1] - 1), z.min(dims[2] - 1))
            })
            .collect();
        let mut starts = vec![0u32; dims[0] * dims[1] * dims[2] + 1];
        for &c in &cell_of {
            starts[c + 1] += 1;
        }
        for c in 1..starts.len() {
            starts[c] += starts[c - 1];
        }
        let mut next = starts.clone();
        let mut entries = vec![([0.0; 3], 0); photons.len()];
        for (i, (photon, &c)) in photons.iter().zip(&cell_of).enumerate() {
            entries[next[c] as usize] = (position(photon).to_array(), i as u32);
            next[c] += 1;
        }
        grid.starts = starts;
        grid.entries = entries;
        grid
    }

    /// The cell coordinates of a point (outside the grid: below 0 or at or above `dims`).
    fn coords(&self, p: Vector) -> [i64; 3] {
        let c = (p - self.origin) * self.inv_cell;
        [c.x, c.y, c.z].map(|v| floor(v) as i64)
    }

    /// The cell coordinate along axis `k` of a point whose coordinate there is `v` (as in `coords`).
    fn coord(&self, k: usize, v: f32) -> i64 {
        floor((v - self.origin[k]) * self.inv_cell) as i64
    }

    fn index(&self, x: usize, y: usize, z: usize) -> usize {
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    /// Replaces the contents of `found` by the photons within squared distance `r2` of `p` (up to the
    /// rounding of the cells' boundaries).
    pub(super) fn within(&self, p: Vector, r2: f32, found: &mut Vec<Found>) {
        found.clear();
        if !p.is_finite() {
            return;
        }
        let r = r2.sqrt();
        let (low, high) = (self.coords(p - r), self.coords(p + r));
        // The cells the box of radius r around the point touches, clipped to the grid; none when the box
        // lies outside it.
        let clip = |k: usize, from: i64, to: i64| from.max(0)..=to.min(self.dims[k] as i64 - 1);
        let q = p.to_array();
        // How far the point is from the slab of cells number c along axis k (0 inside it).
        let gap = |k: usize, c: i64| {
            let start = self.origin[k] + c as f32 * self.cell;
            (start - q[k]).max(q[k] - (start + self.cell)).max(0.0)
        };
        for z in clip(2, low[2], high[2]) {
            let dz2 = gap(2, z).powi(2);
            for y in clip(1, low[1], high[1]) {
                // The ball meets this row of cells along x where x is within `half` of the point's.
                let rest = r2 - dz2 - gap(1, y).powi(2);
                if rest < 0.0 {
                    continue;
                }
                let half = rest.sqrt();
                let xs = clip(0, self.coord(0, q[0] - half), self.coord(0, q[0] + half));
                if xs.is_empty() {
                    continue;
                }
                let first = self.starts[self.index(*xs.start() as usize, y as usize, z as usize)] as usize;
                let end = self.starts[self.index(*xs.end() as usize, y as usize, z as usize) + 1] as usize;
                for &(pos, i) in &self.entries[first..end] {
                    let d2 = (pos[0] - q[0]).powi(2) + (pos[1] - q[1]).powi(2) + (pos[2] - q[2]).powi(2);
                    if d2 <= r2 {
                        found.push(Found::new(d2, i));
                    }
                }
            }
        }
    }
}
