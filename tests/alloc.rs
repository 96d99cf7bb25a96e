//! Steady-state `f64` batch evaluation makes no heap allocation per point
//! (issue 12): a counting global allocator counts the allocations of a
//! batch of 1 000 points and of a batch of 10 000 with the same evaluator,
//! for curves, rect and tri patches, points and first derivatives
//! ([`Jets`]); both counts must be zero.

use exact_bezier::eval::{Evaluator, Jets};
use exact_bezier::{RationalCurve, RectPatch, TriPatch};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// Counts the allocations of the current thread while `COUNTING` is set.
struct Counting;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.with(Cell::get) {
            ALLOCATIONS.with(|a| a.set(a.get() + 1));
        }
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The allocations made by `f`.
fn allocations(f: impl FnOnce()) -> usize {
    ALLOCATIONS.with(|a| a.set(0));
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    ALLOCATIONS.with(Cell::get)
}

/// Parameters: `points` values (curve) or pairs (patch) inside the domain.
fn params(points: usize, per_point: usize) -> Vec<f64> {
    (0..points * per_point)
        .map(|k| (k % 97) as f64 / 200.0)
        .collect()
}

/// Allocations of one batch of `points` points with a warm evaluator.
fn batch_allocations(
    ev: &mut Evaluator<f64>,
    points: usize,
    per_point: usize,
    dim: usize,
) -> usize {
    let ps = params(points, per_point);
    let mut out = vec![0.0; points * dim];
    ev.eval_batch(&ps, &mut out).unwrap(); // warm-up
    let n = allocations(|| ev.eval_batch(&ps, &mut out).unwrap());
    assert!(out.iter().all(|x| x.is_finite()));
    n
}

#[test]
fn f64_batches_allocate_nothing() {
    let p3 = |x: f64, y: f64, z: f64| vec![x, y, z];
    let curve = RationalCurve::new(
        (0..=10)
            .map(|i| vec![i as f64, (i * i % 7) as f64])
            .collect(),
        (0..=10).map(|i| 1.0 + (i % 3) as f64 / 4.0).collect(),
    )
    .unwrap();
    let rect = RectPatch::new(
        (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| p3(i as f64, j as f64, ((i + j) % 3) as f64))
                    .collect()
            })
            .collect(),
        (0..4)
            .map(|i| (0..4).map(|j| 1.0 + ((i * j) % 4) as f64 / 8.0).collect())
            .collect(),
    )
    .unwrap();
    let tri = TriPatch::polynomial(
        (0..=3)
            .map(|j| {
                (0..=3 - j)
                    .map(|i| p3(i as f64, j as f64, (i * j) as f64))
                    .collect()
            })
            .collect(),
    )
    .unwrap();
    let mut evs = [
        (Evaluator::curve(&curve), 1, 2, "curve"),
        (Evaluator::rect(&rect), 2, 3, "rect"),
        (Evaluator::tri(&tri), 2, 3, "tri"),
    ];
    for (ev, per_point, dim, what) in &mut evs {
        for points in [1_000, 10_000] {
            let n = batch_allocations(ev, points, *per_point, *dim);
            assert_eq!(n, 0, "{what}: {n} allocations for a batch of {points}");
        }
    }
    let mut jets = [
        (Jets::curve(&curve), "curve jets"),
        (Jets::rect(&rect), "rect jets"),
        (Jets::tri(&tri), "tri jets"),
    ];
    for (jets, what) in &mut jets {
        for points in [1_000, 10_000] {
            let ps = params(points, jets.params());
            let per_point = (jets.params() + 1) * jets.stride();
            let mut out = vec![0.0; points * per_point];
            jets.eval_batch(&ps, &mut out).unwrap(); // warm-up
            let n = allocations(|| jets.eval_batch(&ps, &mut out).unwrap());
            assert!(out.iter().all(|x| x.is_finite()));
            assert_eq!(n, 0, "{what}: {n} allocations for a batch of {points}");
        }
    }
}

/// The counter itself counts: a batch through `eval_many`, which builds
/// its own net and output, allocates (so a zero above is not a dead counter).
#[test]
fn the_counter_sees_allocations() {
    let c = RationalCurve::polynomial(vec![vec![0.0, 0.0], vec![1.0, 2.0]]).unwrap();
    assert!(allocations(|| drop(c.eval_many(&[0.5]).unwrap())) > 0);
}
