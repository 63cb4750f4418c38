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
/// `first..=last`), for primitives whose ray meets them more than once (meshes): pixel i's
/// are `runs[start[i]..start[i + 1]]`, one buffer for every pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SlabRuns {
    start: Vec<usize>,
    runs: Vec<(u32, u32)>,
}

impl SlabRuns {
    /// From each pixel's runs, in order and disjoint.
    pub fn of_pixels(pixels: Vec<Vec<(u32, u32)>>) -> SlabRuns {
        let mut out = SlabRuns {
            start: vec![0],
            runs: vec![],
        };
        for p in pixels {
            out.runs.extend(p);
            out.start.push(out.runs.len());
        }
        out
    }

    /// From runs in any order per pixel (pixel i's `runs` of `pixel(i)`, for `pixels`
    /// pixels): sorted and merged where they meet or touch; empty runs left out.
    pub fn merged<I: Iterator<Item = (u32, u32)>>(
        pixels: usize,
        pixel: impl Fn(usize) -> I,
    ) -> SlabRuns {
        let mut out = SlabRuns {
            start: Vec::with_capacity(pixels + 1),
            runs: vec![],
        };
        out.start.push(0);
        for i in 0..pixels {
            let from = out.runs.len();
            out.runs.extend(pixel(i).filter(|(a, b)| a <= b));
            out.runs[from..].sort_unstable();
            let mut n = from;
            for j in from..out.runs.len() {
                let (a, b) = out.runs[j];
                match n > from && a <= out.runs[n - 1].1.saturating_add(1) {
                    true => out.runs[n - 1].1 = out.runs[n - 1].1.max(b),
                    false => {
                        out.runs[n] = (a, b);
                        n += 1;
                    }
                }
            }
            out.runs.truncate(n);
            out.start.push(n);
        }
        out
    }

    /// Pixels.
    pub fn pixels(&self) -> usize {
        self.start.len().saturating_sub(1)
    }

    /// Pixel i's runs.
    pub fn pixel(&self, i: usize) -> &[(u32, u32)] {
        &self.runs[self.start[i]..self.start[i + 1]]
    }

    /// Per slab k, the pixels whose membership differs between slab k − 1 and slab k.
    pub fn toggles(&self, slabs: usize) -> Vec<Vec<u32>> {
        let mut t = vec![vec![]; slabs];
        for i in 0..self.pixels() {
            self.pixel(i)
                .iter()
                .for_each(|&run| toggle_run(&mut t, i, run));
        }
        t
    }

    /// The mask of slab k.
    pub fn mask(&self, k: usize) -> Mask {
        let k = k as u32;
        Mask::from_fn(self.pixels(), |i| {
            self.pixel(i).iter().any(|&(a, b)| a <= k && k <= b)
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
