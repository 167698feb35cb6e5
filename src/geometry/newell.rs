//! Newell's method and the planarity check, written once over any [`Ring`]:
//! the word tiers run them on `i128`, the big-integer tier on big integers,
//! the float modes (Newell's alone) on `f32` and `f64`.

use crate::numbers::Ring;

/// Newell's method (the Russian coursework): `a = Σ(yᵢ − yᵢ₊₁)(zᵢ + zᵢ₊₁)`,
/// `b = Σ(zᵢ − zᵢ₊₁)(xᵢ + xᵢ₊₁)`, `c = Σ(xᵢ − xᵢ₊₁)(yᵢ + yᵢ₊₁)`, indices
/// taken around the polygon. `c > 0` when the vertices run
/// counter-clockwise seen from +z.
pub fn newell<T: Ring>(points: &[[T; 3]]) -> [T; 3] {
    let mut normal = [T::zero(), T::zero(), T::zero()];
    for (i, p) in points.iter().enumerate() {
        let q = &points[(i + 1) % points.len()];
        for (axis, n) in normal.iter_mut().enumerate() {
            // (a, b, c) from the pairs (y, z), (z, x), (x, y).
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            *n = n.plus(&p[u].minus(&q[u]).times(&p[v].plus(&q[v])));
        }
    }
    normal
}

/// The first vertex off the plane through vertex 1 and the first two
/// vertices not collinear with it, with what the check found: so that the
/// vertex named is the first one off that plane (Newell's averaged normal
/// would blame others).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OffPlaneVertex<T> {
    /// The vertex off the plane, 0-based.
    pub vertex: usize,
    /// The two vertices after vertex 1 that fix the plane, 0-based.
    pub through: [usize; 2],
    /// The plane's normal `(p_i − p_1) × (p_k − p_1)`.
    pub normal: [T; 3],
    /// `normal · (p_vertex − p_1)`, not zero.
    pub residual: T,
}

/// The planarity check: `None` when every vertex lies on the plane through
/// vertex 1 and the first two vertices not collinear with it (trivially so
/// when all are collinear).
pub fn first_off_plane<T: Ring>(points: &[[T; 3]]) -> Option<OffPlaneVertex<T>> {
    let p1 = &points[0];
    let sub = |p: &[T; 3]| [p[0].minus(&p1[0]), p[1].minus(&p1[1]), p[2].minus(&p1[2])];
    let i = points.iter().position(|p| p != p1)?;
    let u = sub(&points[i]);
    let zero = T::zero();
    let (k, normal) = points.iter().enumerate().skip(i + 1).find_map(|(k, p)| {
        let v = sub(p);
        let n = [
            u[1].times(&v[2]).minus(&u[2].times(&v[1])),
            u[2].times(&v[0]).minus(&u[0].times(&v[2])),
            u[0].times(&v[1]).minus(&u[1].times(&v[0])),
        ];
        n.iter().any(|c| *c != zero).then_some((k, n))
    })?;
    points.iter().enumerate().find_map(|(vertex, point)| {
        let w = sub(point);
        let residual = normal[0].times(&w[0]).plus(&normal[1].times(&w[1])).plus(&normal[2].times(&w[2]));
        (residual != zero).then(|| OffPlaneVertex { vertex, through: [i, k], normal: normal.clone(), residual })
    })
}

#[cfg(test)]
mod tests {
    use num_bigint::BigInt;

    use super::*;

    /// The book's triangle P5 P6 P7, in every number type: one normal.
    #[test]
    fn newell_is_the_same_formula_in_every_number_type() {
        let triangle = [[15, 15, 15], [25, 25, 5], [30, 10, 5]];
        let words = newell(&triangle.map(|p| p.map(i128::from)));
        assert_eq!(words, [-150, -50, -200], "3x + y + 4z − 120 = 0, scaled by −50: clockwise");
        assert_eq!(newell(&triangle.map(|p| p.map(BigInt::from))), words.map(BigInt::from));
        assert_eq!(newell(&triangle.map(|p| p.map(f64::from))), words.map(|v| v as f64));
    }

    /// A square with one corner lifted: vertex 4 is named, off the plane
    /// through vertices 1, 2 and 3, by the same amount in both integer types.
    #[test]
    fn the_first_vertex_off_the_plane_is_named_in_every_integer_type() {
        let square = [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 3]];
        let words = first_off_plane(&square.map(|p| p.map(i128::from))).expect("not planar");
        assert_eq!((words.vertex, words.through, words.normal, words.residual), (3, [1, 2], [0, 0, 16], 48));
        let big = first_off_plane(&square.map(|p| p.map(BigInt::from))).expect("not planar");
        assert_eq!(big.residual, BigInt::from(48));
        let flat = [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]];
        assert_eq!(first_off_plane(&flat.map(|p| p.map(i128::from))), None);
        let collinear = [[0, 0, 0], [1, 1, 1], [2, 2, 2]];
        assert_eq!(first_off_plane(&collinear.map(|p| p.map(i128::from))), None);
    }
}
