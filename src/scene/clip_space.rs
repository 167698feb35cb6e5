//! Clip-space vertices `[x, y, z, w]` as OpenGL gives them to the
//! rasterizer: clipped exactly against the view volume, divided by w, and
//! mapped by the viewport onto the raster.
//!
//! - **View volume.** `−w ≤ x ≤ w`, `−w ≤ y ≤ w`, `−w ≤ z ≤ w` (so `w ≥ 0`),
//!   clipped one plane at a time (Sutherland–Hodgman), each new vertex at
//!   `a + t·(b − a)` with `t = d_a / (d_a − d_b)`, d the distance inside the
//!   plane, all exact. A vertex on a plane is inside.
//! - **Viewport** (OpenGL's, y up like zsim's raster): `x' = (x/w + 1)·W/2`,
//!   `y' = (y/w + 1)·H/2`, and depth `z' = (z/w + 1)/2 · (2^depth_bits − 1)`,
//!   the default depth range 0 … 1 spread over the z-buffer's levels, so the
//!   near plane is 0 and the far plane the largest level: use the depth test
//!   `less` (OpenGL's default) for the nearer polygon to win. z/w is linear on
//!   the screen, so a planar polygon stays planar.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::numbers::Exact;

/// The view volume's planes, in the order clipped: x, then y, then z; each
/// as (axis, sign): inside when `w + sign·coordinate ≥ 0`.
const PLANES: [(usize, i128); 6] = [(0, 1), (0, -1), (1, 1), (1, -1), (2, 1), (2, -1)];

/// What clipping left of a polygon.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Clipped {
    /// The part inside the view volume, mapped onto the raster, and how many
    /// of the given vertices lay inside.
    Inside {
        /// The vertices on the raster (x', y', z'), exact however large.
        vertices: Vec<[Exact; 3]>,
        /// How many of the given vertices were inside the view volume.
        inside: usize,
    },
    /// Nothing of it lies inside the view volume (or only a point or a line).
    Outside,
}

/// Clips a polygon given in clip space and maps it onto a `width × height`
/// raster whose z-buffer holds `0 ..= depth_max`. The clipping runs in
/// arbitrary-precision rationals, so it never overflows.
pub fn to_raster(vertices: &[[Exact; 4]], width: u32, height: u32, depth_max: u32) -> Clipped {
    let zero = BigRational::zero();
    let vertices: Vec<[BigRational; 4]> = vertices.iter().map(|v| v.each_ref().map(Exact::to_big)).collect();
    let inside = vertices.iter().filter(|v| PLANES.iter().all(|&(axis, sign)| distance(v, axis, sign) >= zero)).count();
    let mut polygon = vertices;
    for (axis, sign) in PLANES {
        let mut out: Vec<[BigRational; 4]> = Vec::with_capacity(polygon.len() + 1);
        for i in 0..polygon.len() {
            let (a, b) = (&polygon[i], &polygon[(i + 1) % polygon.len()]);
            let (da, db) = (distance(a, axis, sign), distance(b, axis, sign));
            if da >= zero {
                out.push(a.clone());
            }
            if (da >= zero) != (db >= zero) {
                let t = &da / (&da - &db);
                out.push(std::array::from_fn(|k| &a[k] + &t * (&b[k] - &a[k])));
            }
        }
        out.dedup();
        while out.len() > 1 && out.first() == out.last() {
            out.pop();
        }
        polygon = out;
        if polygon.len() < 3 {
            return Clipped::Outside;
        }
    }
    let one = BigRational::one();
    let half = |n: u32| BigRational::new(BigInt::from(n), BigInt::from(2));
    let (w_half, h_half, depth_half) = (half(width), half(height), half(depth_max));
    let mut mapped = Vec::with_capacity(polygon.len());
    for [x, y, z, w] in polygon {
        if w.is_zero() {
            // Only the origin has w = 0 inside the volume: a point, not a polygon.
            return Clipped::Outside;
        }
        let map = |c: BigRational, half: &BigRational| Exact::from((c / &w + &one) * half);
        mapped.push([map(x, &w_half), map(y, &h_half), map(z, &depth_half)]);
    }
    Clipped::Inside { vertices: mapped, inside }
}

/// How far inside the plane `w + sign·coordinate ≥ 0` a vertex lies.
fn distance(v: &[BigRational; 4], axis: usize, sign: i128) -> BigRational {
    if sign > 0 { &v[3] + &v[axis] } else { &v[3] - &v[axis] }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numbers::Q;

    fn q(n: i128, d: i128) -> Exact {
        Exact::Word(Q::new(n, d))
    }

    /// A triangle inside the volume maps by the viewport exactly: x' = (x/w + 1)·W/2.
    #[test]
    fn viewport_maps_clip_space_onto_the_raster() {
        let triangle = [
            [q(-1, 2), q(0, 1), q(0, 1), q(1, 1)],
            [q(1, 1), q(1, 1), q(1, 1), q(2, 1)],
            [q(0, 1), q(-1, 1), q(-1, 1), q(1, 1)],
        ];
        let Clipped::Inside { vertices, inside } = to_raster(&triangle, 8, 4, 15) else { panic!("inside") };
        assert_eq!(inside, 3);
        assert_eq!(vertices[0], [q(2, 1), q(2, 1), q(15, 2)]);
        assert_eq!(vertices[1], [q(6, 1), q(3, 1), q(45, 4)]);
        assert_eq!(vertices[2], [q(4, 1), q(0, 1), q(0, 1)]);
    }

    /// A vertex behind the eye (w < 0) is clipped away exactly: the near
    /// plane z = −w cuts the edges, and what remains lies in front.
    #[test]
    fn a_vertex_behind_the_eye_is_clipped_at_the_near_plane() {
        let triangle = [
            [q(0, 1), q(0, 1), q(0, 1), q(1, 1)],
            [q(1, 2), q(0, 1), q(0, 1), q(1, 1)],
            [q(0, 1), q(0, 1), q(-3, 1), q(-1, 1)],
        ];
        let Clipped::Inside { vertices, inside } = to_raster(&triangle, 2, 2, 10) else { panic!("inside") };
        assert_eq!(inside, 2);
        // Every vertex left has z' ≥ 0: nothing in front of the near plane survives as negative depth.
        assert!(vertices.iter().all(|v| v[2] >= q(0, 1)), "{vertices:?}");
        assert_eq!(vertices.len(), 4);
        let all_behind = [
            [q(0, 1), q(0, 1), q(-3, 1), q(-1, 1)],
            [q(1, 1), q(0, 1), q(-3, 1), q(-1, 1)],
            [q(0, 1), q(1, 1), q(-3, 1), q(-1, 1)],
        ];
        assert_eq!(to_raster(&all_behind, 2, 2, 10), Clipped::Outside);
    }
}
