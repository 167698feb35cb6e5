//! Clipping to the view volume, the winding test and the course's DDA, over
//! any [`Scalar`].

use super::scalar::{Scalar, Vertex};

/// Whether a screen triangle's vertices run clockwise as the image shows
/// them (y down), the front faces `cull` keeps.
pub(super) fn clockwise<S: Scalar>(v: &[Vertex<S>]) -> bool {
    let cross =
        v[1][0].sub(&v[0][0]).mul(&v[2][1].sub(&v[0][1])).sub(&v[2][0].sub(&v[0][0]).mul(&v[1][1].sub(&v[0][1])));
    cross < S::int(0)
}

/// The view volume's planes, in the order clipped: near and far first
/// (−w ≤ z ≤ w), then −w ≤ x ≤ w and −w ≤ y ≤ w; each as (axis, sign).
pub(super) const PLANES: [(usize, i8); 6] = [(2, -1), (2, 1), (0, -1), (0, 1), (1, -1), (1, 1)];

/// Clips a triangle in clip space to the view volume (Sutherland–Hodgman, one
/// plane at a time), interpolating every component linearly.
pub(super) fn clip<S: Scalar>(polygon: Vec<Vertex<S>>) -> Vec<Vertex<S>> {
    let zero = S::int(0);
    let mut polygon = polygon;
    for (axis, sign) in PLANES {
        // How far inside the plane: w − x for x ≤ w, w + x for −w ≤ x.
        let distance = |v: &Vertex<S>| if sign > 0 { v[3].sub(&v[axis]) } else { v[3].add(&v[axis]) };
        let mut out = Vec::new();
        for i in 0..polygon.len() {
            let (a, b) = (&polygon[i], &polygon[(i + 1) % polygon.len()]);
            let (da, db) = (distance(a), distance(b));
            if da >= zero {
                out.push(a.clone());
            }
            if (da >= zero) != (db >= zero) {
                // Where the edge a → b crosses the plane, measured from b.
                let t = db.div(&db.sub(&da));
                out.push(b.iter().zip(a).map(|(x, y)| x.add(&t.mul(&y.sub(x)))).collect());
            }
        }
        polygon = out;
        if polygon.len() < 3 {
            return Vec::new();
        }
    }
    polygon
}

/// The course's DDA: from `a` to `b` along coordinate `d`, every point where
/// `d` is an integer, `a_d` included when it is one, `b_d` never.
pub(super) struct Dda<S> {
    pub(super) p: Vec<S>,
    s: Vec<S>,
    end: S,
    d: usize,
}

impl<S: Scalar> Dda<S> {
    pub(super) fn new(a: &[S], b: &[S], d: usize) -> Option<Dda<S>> {
        if a[d] == b[d] {
            return None;
        }
        let (a, b) = if a[d] > b[d] { (b, a) } else { (a, b) };
        let delta = b[d].sub(&a[d]);
        let s: Vec<S> = a.iter().zip(b).map(|(x, y)| y.sub(x).div(&delta)).collect();
        let e = a[d].ceil().sub(&a[d]);
        let p = a.iter().zip(&s).map(|(x, step)| x.add(&e.mul(step))).collect();
        Some(Dda { p, s, end: b[d].clone(), d })
    }

    pub(super) fn live(&self) -> bool {
        self.p[self.d] < self.end
    }

    /// The integer the point has reached along `d`.
    pub(super) fn at(&self) -> i64 {
        self.p[self.d].to_f64().round() as i64
    }

    /// Steps (with `follow` in step) while live and before `target` along
    /// `d`, as the walk would. In exact arithmetic it jumps there at once,
    /// to the same point: `⌈min(target, end) − p_d⌉` steps of `s` added as one.
    pub(super) fn skip_before(&mut self, target: i64, mut follow: Option<&mut Dda<S>>) {
        if !S::EXACT {
            while self.live() && self.at() < target {
                self.step();
                if let Some(f) = follow.as_deref_mut() {
                    f.step();
                }
            }
            return;
        }
        let target = S::int(target);
        if self.p[self.d] >= target {
            return;
        }
        let bound = if self.end < target { self.end.clone() } else { target };
        let steps = bound.sub(&self.p[self.d]).ceil();
        self.advance(&steps);
        if let Some(f) = follow {
            f.advance(&steps);
        }
    }

    pub(super) fn advance(&mut self, steps: &S) {
        for (p, s) in self.p.iter_mut().zip(&self.s) {
            *p = p.add(&s.mul(steps));
        }
    }

    pub(super) fn step(&mut self) {
        for (p, s) in self.p.iter_mut().zip(&self.s) {
            *p = p.add(s);
        }
    }
}
