//! A primitive's slabs per pixel, as the interval routes give them (one run per pixel,
//! [`SlabRanges`]) and meshes (several, [`SlabRuns`]), and the per-slab flips both are swept
//! by. A leaf module: the routes (`ranges`), the imports (`sampled`), the footprints and both
//! drivers use it and it uses none of them, so that none of those needs another back.

use crate::slice::Mask;

/// Per pixel, the slabs primitive P meets: `first..=last` (empty when first > last).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SlabRanges(pub Vec<(u32, u32)>);

impl SlabRanges {
    /// Per slab k, the pixels whose membership differs between slab k − 1 and slab k: those
    /// whose range starts at k or ended at k − 1 (slab 0: none).
    pub fn toggles(&self, slabs: usize) -> Vec<Vec<u32>> {
        let mut t = vec![vec![]; slabs];
        for (i, &run) in self.0.iter().enumerate() {
            toggle_run(&mut t, i, run);
        }
        t
    }

    /// The mask of slab k.
    pub fn mask(&self, k: usize) -> Mask {
        let k = k as u32;
        Mask::from_fn(self.0.len(), |i| {
            let (a, b) = self.0[i];
            a <= k && k <= b
        })
    }
}

/// Per pixel, the runs of slabs inside a primitive (disjoint, sorted, not touching:
/// `first..=last`), for primitives whose ray meets them more than once (meshes).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SlabRuns(pub Vec<Vec<(u32, u32)>>);

impl SlabRuns {
    /// From runs in any order per pixel: sorted and merged where they meet or touch.
    pub fn merged(mut runs: Vec<Vec<(u32, u32)>>) -> SlabRuns {
        for r in &mut runs {
            r.retain(|(a, b)| a <= b);
            r.sort_unstable();
            let mut out: Vec<(u32, u32)> = Vec::with_capacity(r.len());
            for &(a, b) in r.iter() {
                match out.last_mut() {
                    Some(last) if a <= last.1.saturating_add(1) => last.1 = last.1.max(b),
                    _ => out.push((a, b)),
                }
            }
            *r = out;
        }
        SlabRuns(runs)
    }

    /// Per slab k, the pixels whose membership differs between slab k − 1 and slab k.
    pub fn toggles(&self, slabs: usize) -> Vec<Vec<u32>> {
        let mut t = vec![vec![]; slabs];
        for (i, runs) in self.0.iter().enumerate() {
            runs.iter().for_each(|&run| toggle_run(&mut t, i, run));
        }
        t
    }

    /// The mask of slab k.
    pub fn mask(&self, k: usize) -> Mask {
        let k = k as u32;
        Mask::from_fn(self.0.len(), |i| {
            self.0[i].iter().any(|&(a, b)| a <= k && k <= b)
        })
    }
}

/// Record that pixel i enters slab `first` and leaves after slab `last` (an empty run,
/// first > last, records nothing): the flips [`SlabRanges::toggles`] and
/// [`SlabRuns::toggles`] list per slab.
pub fn toggle_run(t: &mut [Vec<u32>], i: usize, (first, last): (u32, u32)) {
    if first > last {
        return;
    }
    if first > 0 && (first as usize) < t.len() {
        t[first as usize].push(i as u32);
    }
    if (last as usize) + 1 < t.len() {
        t[last as usize + 1].push(i as u32);
    }
}
