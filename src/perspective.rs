//! Perspective (seed 002 §2.2, seed 004): near-plane clipping by the seed's
//! formula, the projective map to the picture plane, and the w-buffer's
//! eye-space depth, all exact.
//!
//! The eye is at `(W/2, H/2, d)` looking toward −z; the picture plane is
//! z = 0. Each polygon is first clipped against the plane `z = d − n`,
//! keeping the part with `z ≤ d − n`; then each vertex maps to
//! `x' = W/2 + (x − W/2)·d/(d − z)`, `y' = H/2 + (y − H/2)·d/(d − z)`,
//! `z' = d·z/(d − z)`. That map is projective, so the image of a planar
//! polygon is planar and the book's rules apply unchanged with z' as depth.

use num_traits::{CheckedAdd, CheckedDiv, CheckedMul, CheckedSub};

use crate::depth::Depth;
use crate::exact::{Exact, Q};

/// The perspective effect's settings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Perspective {
    /// `d`: the eye's distance from the picture plane.
    pub distance: Q,
    /// `n > 0`: the seed's small offset; polygons are clipped at `z = d − n`.
    pub near: Q,
    /// Keep the eye-space depth z in the z-buffer (the w-buffer of seed 004)
    /// instead of z'.
    pub store_w: bool,
}

/// How a polygon fared against the near plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Clip {
    /// No perspective: nothing to clip.
    NotClipped,
    /// With perspective: `front` of the polygon's vertices lie in front of the
    /// near plane (`z ≤ d − n`) out of `of`; the kept part is drawn as one polygon.
    Kept {
        /// Vertices in front.
        front: usize,
        /// Vertices in all.
        of: usize,
    },
    /// Every vertex lies behind the near plane: nothing is drawn.
    Away,
    /// Given in clip space: `inside` of its `of` vertices lay inside the view
    /// volume; the part inside is drawn ([`crate::clip_space`]).
    View {
        /// Vertices inside the view volume.
        inside: usize,
        /// Vertices in all.
        of: usize,
    },
    /// Given in clip space, and nothing of it lies inside the view volume.
    ViewAway,
}

impl Perspective {
    /// The near plane's z: `d − n`.
    pub fn near_plane(&self) -> Q {
        self.distance - self.near
    }

    /// Sutherland–Hodgman against `z = d − n`, keeping `z ≤ d − n`, with the
    /// seed's formula for a new vertex D on edge AC:
    /// `D.t = A.t + (C.t − A.t)·(D.z − A.z)/(C.z − A.z)`. For a triangle this
    /// is the seed's case analysis: 0 vertices in front give nothing, 1 the
    /// triangle CDE, 2 the quadrilateral DABE (kept as one polygon), 3 the
    /// whole. `None` when a value does not fit `i128`.
    pub fn clip(&self, vertices: &[[Q; 3]]) -> Option<(Vec<[Q; 3]>, Clip)> {
        let plane = self.near_plane();
        let inside = |v: &[Q; 3]| v[2] <= plane;
        let front = vertices.iter().filter(|v| inside(v)).count();
        if front == vertices.len() {
            return Some((vertices.to_vec(), Clip::Kept { front, of: vertices.len() }));
        }
        if front == 0 {
            return Some((Vec::new(), Clip::Away));
        }
        let crossing = |a: &[Q; 3], c: &[Q; 3]| -> Option<[Q; 3]> {
            let t = plane.checked_sub(&a[2])?.checked_div(&c[2].checked_sub(&a[2])?)?;
            let along = |i: usize| a[i].checked_add(&c[i].checked_sub(&a[i])?.checked_mul(&t)?);
            Some([along(0)?, along(1)?, plane])
        };
        let mut out = Vec::with_capacity(vertices.len() + 2);
        for (i, end) in vertices.iter().enumerate() {
            let start = &vertices[(i + vertices.len() - 1) % vertices.len()];
            match (inside(start), inside(end)) {
                (true, true) => out.push(*end),
                (true, false) => out.push(crossing(start, end)?),
                (false, true) => {
                    out.push(crossing(start, end)?);
                    out.push(*end);
                }
                (false, false) => {}
            }
        }
        Some((out, Clip::Kept { front, of: vertices.len() }))
    }

    /// The projective map of a vertex in front of the near plane onto the
    /// picture plane, with its depth z'. `None` when a value does not fit `i128`.
    pub fn project(&self, v: [Q; 3], width: u32, height: u32) -> Option<[Q; 3]> {
        let d = self.distance;
        let scale = d.checked_div(&d.checked_sub(&v[2])?)?;
        let map = |value: Q, size: u32| -> Option<Q> {
            let centre = Q::new(i128::from(size), 2);
            centre.checked_add(&value.checked_sub(&centre)?.checked_mul(&scale)?)
        };
        Some([map(v[0], width)?, map(v[1], height)?, v[2].checked_mul(&scale)?])
    }

    /// The eye-space depth for a projected depth: `z = d·z'/(d + z')`, in
    /// 128 bits where the products fit, else in big integers. A projected
    /// depth of a polygon in front of the eye has `d + z' > 0`.
    pub fn eye_depth(&self, projected: &Depth) -> Depth {
        let (p, q) = (*self.distance.numer(), *self.distance.denom());
        // z = (p/q)(n/den) / (p/q + n/den) = p·n / (p·den + q·n).
        let words = |(n, den): (i128, i128)| {
            let denominator = p.checked_mul(den)?.checked_add(q.checked_mul(n)?)?;
            let numerator = p.checked_mul(n)?;
            // Within the bounds every 128-bit depth keeps (`Depth::from_big`).
            (numerator.unsigned_abs() < 1 << 125 && denominator.unsigned_abs() < 1 << 124)
                .then(|| Depth::from_fraction(numerator, denominator))
        };
        match projected.fraction().and_then(words) {
            Some(depth) => depth,
            None => {
                let z = projected.value().to_big();
                let distance = Exact::Word(self.distance).to_big();
                Depth::from_exact(Exact::from(&distance * &z / (&distance + &z)))
            }
        }
    }

    /// The eye-space depth of an exact projected value (for reports); `None`
    /// when `d + z' = 0` (the point is at infinity).
    pub fn eye_value(&self, projected: &Exact) -> Option<Exact> {
        let (distance, z) = (Exact::Word(self.distance).to_big(), projected.to_big());
        let sum = &distance + &z;
        (!num_traits::Zero::is_zero(&sum)).then(|| Exact::from(distance * z / sum))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(v: i128) -> Q {
        Q::from_integer(v)
    }

    fn perspective() -> Perspective {
        Perspective { distance: q(40), near: q(2), store_w: false }
    }

    #[test]
    fn clipping_follows_the_seeds_four_cases() {
        let p = perspective(); // near plane z = 38
        let triangle = |zs: [i128; 3]| vec![[q(0), q(0), q(zs[0])], [q(10), q(0), q(zs[1])], [q(0), q(10), q(zs[2])]];
        assert_eq!(p.clip(&triangle([50, 60, 70])).unwrap().1, Clip::Away, "0 in front: not drawn");
        let (one, clip) = p.clip(&triangle([0, 60, 70])).unwrap();
        assert_eq!((one.len(), clip), (3, Clip::Kept { front: 1, of: 3 }), "1 in front: the triangle CDE");
        let (two, clip) = p.clip(&triangle([0, 0, 78])).unwrap();
        assert_eq!((two.len(), clip), (4, Clip::Kept { front: 2, of: 3 }), "2 in front: the quadrilateral DABE");
        let (three, _) = p.clip(&triangle([0, 1, 2])).unwrap();
        assert_eq!(three.len(), 3, "3 in front: the whole");
        // D on AC by the seed's formula: A = (0, 10, 0), C = (0, 0, 0)… here A(10,0,0) to C(0,10,78): t = 38/78.
        assert!(two.iter().all(|v| v[2] <= q(38)));
        assert!(two.contains(&[Q::new(10 * 40, 78), Q::new(380, 78), q(38)]));
    }

    #[test]
    fn projection_and_eye_depth_invert_each_other() {
        let p = perspective();
        let v = p.project([q(26), q(6), q(20)], 32, 32).unwrap();
        // scale d/(d − z) = 40/20 = 2: x' = 16 + 10·2 = 36, y' = 16 − 10·2 = −4, z' = 40.
        assert_eq!(v, [q(36), q(-4), q(40)]);
        assert_eq!(p.eye_value(&Exact::Word(v[2])), Some(Exact::Word(q(20))));
        assert_eq!(p.eye_depth(&Depth::from_fraction(40, 1)).value(), q(20));
    }
}
