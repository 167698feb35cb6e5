//! Perspective (the Russian coursework §2.2, the Ukrainian Wikipedia): near-plane clipping by the coursework's
//! formula, the projective map to the picture plane, and the w-buffer's
//! eye-space depth, all exact.
//!
//! The eye is at `(W/2, H/2, d)` looking toward −z; the picture plane is
//! z = 0. Each polygon is first clipped against the plane `z = d − n`,
//! keeping the part with `z ≤ d − n`; then each vertex maps to
//! `x' = W/2 + (x − W/2)·d/(d − z)`, `y' = H/2 + (y − H/2)·d/(d − z)`,
//! `z' = d·z/(d − z)`. That map is projective, so the image of a planar
//! polygon is planar and the book's rules apply unchanged with z' as depth.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{CheckedAdd, CheckedDiv, CheckedMul, CheckedSub};

use crate::numbers::{Exact, Q};
use crate::raster::depth::Depth;

/// The perspective effect's settings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Perspective {
    /// `d`: the eye's distance from the picture plane.
    pub distance: Q,
    /// `n > 0`: the coursework's small offset; polygons are clipped at `z = d − n`.
    pub near: Q,
    /// Keep the eye-space depth z in the z-buffer (the w-buffer of the Ukrainian Wikipedia)
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
    /// volume; the part inside is drawn ([`crate::scene::clip_space`]).
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
    /// is the coursework's case analysis: 0 vertices in front give nothing, 1 the
    /// triangle CDE, 2 the quadrilateral DABE (kept as one polygon), 3 the
    /// whole. Exact however large (new vertices in big rationals where 128
    /// bits overflow).
    pub fn clip(&self, vertices: &[[Exact; 3]]) -> (Vec<[Exact; 3]>, Clip) {
        let plane = Exact::Word(self.near_plane());
        let inside = |v: &[Exact; 3]| v[2] <= plane;
        let front = vertices.iter().filter(|v| inside(v)).count();
        if front == vertices.len() {
            return (vertices.to_vec(), Clip::Kept { front, of: vertices.len() });
        }
        if front == 0 {
            return (Vec::new(), Clip::Away);
        }
        let crossing = |a: &[Exact; 3], c: &[Exact; 3]| -> [Exact; 3] {
            let [a, c] = [a, c].map(|v| v.each_ref().map(Exact::to_big));
            let t = (plane.to_big() - &a[2]) / (&c[2] - &a[2]);
            let along = |i: usize| Exact::from(&a[i] + (&c[i] - &a[i]) * &t);
            [along(0), along(1), plane.clone()]
        };
        let mut out = Vec::with_capacity(vertices.len() + 2);
        for (i, end) in vertices.iter().enumerate() {
            let start = &vertices[(i + vertices.len() - 1) % vertices.len()];
            match (inside(start), inside(end)) {
                (true, true) => out.push(end.clone()),
                (true, false) => out.push(crossing(start, end)),
                (false, true) => {
                    out.push(crossing(start, end));
                    out.push(end.clone());
                }
                (false, false) => {}
            }
        }
        (out, Clip::Kept { front, of: vertices.len() })
    }

    /// The projective map of a vertex in front of the near plane onto the
    /// picture plane, with its depth z': `x' = c + (x − c)·d/(d − z)`,
    /// `z' = z·d/(d − z)`. Exact however large (in big rationals where 128
    /// bits overflow).
    pub fn project(&self, v: &[Exact; 3], width: u32, height: u32) -> [Exact; 3] {
        let words = || {
            let [x, y, z] = [v[0].word()?, v[1].word()?, v[2].word()?];
            let d = self.distance;
            let scale = d.checked_div(&d.checked_sub(&z)?)?;
            let map = |value: Q, size: u32| -> Option<Q> {
                let centre = Q::new(i128::from(size), 2);
                centre.checked_add(&value.checked_sub(&centre)?.checked_mul(&scale)?)
            };
            Some([map(x, width)?, map(y, height)?, z.checked_mul(&scale)?].map(Exact::Word))
        };
        words().unwrap_or_else(|| {
            let [x, y, z] = v.each_ref().map(Exact::to_big);
            let d = Exact::Word(self.distance).to_big();
            let scale = &d / (&d - &z);
            let centre = |size: u32| BigRational::new(BigInt::from(size), BigInt::from(2));
            let map = |value: BigRational, size: u32| Exact::from(centre(size) + (value - centre(size)) * &scale);
            [map(x, width), map(y, height), Exact::from(z * &scale)]
        })
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
        let e = |v: i128| Exact::Word(q(v));
        let triangle = |zs: [i128; 3]| vec![[e(0), e(0), e(zs[0])], [e(10), e(0), e(zs[1])], [e(0), e(10), e(zs[2])]];
        assert_eq!(p.clip(&triangle([50, 60, 70])).1, Clip::Away, "0 in front: not drawn");
        let (one, clip) = p.clip(&triangle([0, 60, 70]));
        assert_eq!((one.len(), clip), (3, Clip::Kept { front: 1, of: 3 }), "1 in front: the triangle CDE");
        let (two, clip) = p.clip(&triangle([0, 0, 78]));
        assert_eq!((two.len(), clip), (4, Clip::Kept { front: 2, of: 3 }), "2 in front: the quadrilateral DABE");
        let (three, _) = p.clip(&triangle([0, 1, 2]));
        assert_eq!(three.len(), 3, "3 in front: the whole");
        // D on AC by the coursework's formula: A = (0, 10, 0), C = (0, 0, 0)… here A(10,0,0) to C(0,10,78): t = 38/78.
        assert!(two.iter().all(|v| v[2] <= e(38)));
        assert!(two.contains(&[Q::new(10 * 40, 78), Q::new(380, 78), q(38)].map(Exact::Word)));
    }

    #[test]
    fn projection_and_eye_depth_invert_each_other() {
        let p = perspective();
        let v = p.project(&[q(26), q(6), q(20)].map(Exact::Word), 32, 32);
        // scale d/(d − z) = 40/20 = 2: x' = 16 + 10·2 = 36, y' = 16 − 10·2 = −4, z' = 40.
        assert_eq!(v, [q(36), q(-4), q(40)].map(Exact::Word));
        assert_eq!(p.eye_value(&v[2]), Some(Exact::Word(q(20))));
        assert_eq!(p.eye_depth(&Depth::from_fraction(40, 1)).value(), q(20));
    }
}
