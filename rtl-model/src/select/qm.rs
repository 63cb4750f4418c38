//! Exact two-level minimization (Quine-McCluskey) of the select-logic truth tables.
//!
//! The thesis derives the select equations of §2.3.3-2.3.5 from hand-made Karnaugh maps. This
//! module is the machine check: [`minimize`] computes a minimum sum-of-products cover of a
//! truth table with don't-cares, so the printed equations can be compared with a true optimum.
//!
//! The method is the textbook one. All prime implicants of on ∪ dc come from repeatedly
//! merging cubes that differ in one literal. A cheapest set of primes covering the on-set is
//! then found by branch and bound: essential primes and row/column dominance shrink the table,
//! a Lagrangian lower bound prunes and orders the branches. Every container is ordered, so the
//! result is fully deterministic.

use std::collections::BTreeSet;

use super::sop::Cube;

/// Minimal sum-of-products cover of the on-set `on`, free to use the don't-care set `dc`.
///
/// Minterms are bit patterns over `n` variables (bit `i` = variable `i`); bits at or above `n`
/// are ignored. Everything not in on ∪ dc is off; a minterm in both `on` and `dc` counts as on.
/// The cover has the fewest cubes, then the fewest literals; among equally good covers the
/// (deterministic) search order picks one. The cubes come sorted by `(care, value)`. An empty
/// vector is the constant 0, a single cube with `care == 0` the constant 1.
///
/// Intended for `n <= 12`. Exact covering is exponential in the worst case; functions of up
/// to 8 variables with structure take milliseconds, random ones up to about a second. Never
/// panics.
pub fn minimize(n: usize, on: &[u32], dc: &[u32]) -> Vec<Cube> {
    let mask = var_mask(n);
    let on: Vec<u32> = on
        .iter()
        .map(|m| m & mask)
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    if on.is_empty() {
        return Vec::new();
    }
    let primes = prime_implicants(mask, &on, dc);
    let table = Table::new(&primes, &on);
    let mut cover: Vec<Cube> = table
        .min_cover()
        .into_iter()
        .map(|r| table.cubes[r])
        .collect();
    cover.sort();
    cover
}

/// The mask of the low `n` bits.
fn var_mask(n: usize) -> u32 {
    if n >= 32 {
        u32::MAX
    } else {
        (1u32 << n) - 1
    }
}

/// The set bits of `x`, lowest first, each as a one-bit mask.
fn bits(mut x: u32) -> impl Iterator<Item = u32> {
    std::iter::from_fn(move || {
        let low = x & x.wrapping_neg();
        x &= !low;
        (low != 0).then_some(low)
    })
}

/// All prime implicants of on ∪ dc over the variables in `mask`, sorted by `(care, value)`.
///
/// Each round merges pairs of cubes with the same care set whose values differ in one bit;
/// the cubes that took part in no merge are prime.
fn prime_implicants(mask: u32, on: &[u32], dc: &[u32]) -> Vec<Cube> {
    let mut level: BTreeSet<Cube> = on
        .iter()
        .chain(dc)
        .map(|&m| Cube {
            care: mask,
            value: m & mask,
        })
        .collect();
    let mut primes = Vec::new();
    while !level.is_empty() {
        let mut next = BTreeSet::new();
        let mut merged = BTreeSet::new();
        for c in &level {
            for bit in bits(c.care & !c.value) {
                let partner = Cube {
                    care: c.care,
                    value: c.value | bit,
                };
                if level.contains(&partner) {
                    next.insert(Cube {
                        care: c.care & !bit,
                        value: c.value,
                    });
                    merged.insert(*c);
                    merged.insert(partner);
                }
            }
        }
        primes.extend(level.difference(&merged));
        level = next;
    }
    primes.sort();
    primes
}

/// The members of a bit set given as words, lowest first.
fn ones(words: impl Iterator<Item = u64>) -> impl Iterator<Item = usize> {
    words.enumerate().flat_map(|(w, word)| {
        let mut rest = word;
        std::iter::from_fn(move || {
            let b = rest.trailing_zeros() as usize;
            rest &= rest.wrapping_sub(1);
            (b < 64).then_some(w * 64 + b)
        })
    })
}

/// The words of `a ∩ b`.
fn and<'a>(a: &'a [u64], b: &'a [u64]) -> impl Iterator<Item = u64> + 'a {
    a.iter().zip(b).map(|(x, y)| x & y)
}

fn count(set: &[u64]) -> u32 {
    set.iter().map(|w| w.count_ones()).sum()
}

/// Equal-width bit sets stored in one allocation.
struct BitRows {
    words: usize,
    data: Vec<u64>,
}

impl BitRows {
    fn new(rows: usize, bits: usize) -> BitRows {
        let words = bits.div_ceil(64);
        BitRows {
            words,
            data: vec![0; rows * words],
        }
    }

    fn row(&self, i: usize) -> &[u64] {
        &self.data[i * self.words..(i + 1) * self.words]
    }

    fn row_mut(&mut self, i: usize) -> &mut [u64] {
        &mut self.data[i * self.words..(i + 1) * self.words]
    }

    fn insert(&mut self, i: usize, bit: usize) {
        self.data[i * self.words + bit / 64] |= 1 << (bit % 64);
    }
}

pub static NODES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// The first `n` rows of a [`BitRows`], with summaries that reject most subset tests fast.
struct Subsets<'a> {
    sets: &'a BitRows,
    count: Vec<u32>,
    /// All words of a set ORed together.
    fold: Vec<u64>,
}

impl Subsets<'_> {
    fn new(sets: &BitRows, n: usize) -> Subsets<'_> {
        Subsets {
            sets,
            count: (0..n).map(|i| count(sets.row(i))).collect(),
            fold: (0..n)
                .map(|i| sets.row(i).iter().fold(0, |f, w| f | w))
                .collect(),
        }
    }

    /// Whether set `a` is a subset of set `b`.
    fn subset(&self, a: usize, b: usize) -> bool {
        self.count[a] <= self.count[b]
            && self.fold[a] & !self.fold[b] == 0
            && (self.sets.row(a).iter())
                .zip(self.sets.row(b))
                .all(|(x, y)| x & !y == 0)
    }
}

/// Subgradient steps per lower bound.
const BOUND_STEPS: usize = 30;

/// The covering problem: rows are the useful primes, columns the on-set minterms.
struct Table {
    cubes: Vec<Cube>,
    /// Columns (indices into the on-set) each row covers.
    covers: BitRows,
    columns: usize,
}

impl Table {
    /// Rows for the primes that cover at least one on minterm.
    fn new(primes: &[Cube], on: &[u32]) -> Table {
        let cubes: Vec<Cube> = primes
            .iter()
            .copied()
            .filter(|p| on.iter().any(|&m| p.contains(m)))
            .collect();
        let mut covers = BitRows::new(cubes.len(), on.len());
        for (r, p) in cubes.iter().enumerate() {
            for (j, &m) in on.iter().enumerate() {
                if p.contains(m) {
                    covers.insert(r, j);
                }
            }
        }
        Table {
            cubes,
            covers,
            columns: on.len(),
        }
    }

    /// Row indices of a cover with the fewest rows and, among those, the fewest literals.
    ///
    /// First the number of rows: a search for any cover of at most `k` rows, for growing
    /// `k`. A tight limit prunes hard, so this is cheaper than searching down from a poor
    /// first cover. Then the literals, by a second search among covers of `k` rows.
    fn min_cover(&self) -> Vec<usize> {
        let mut open = vec![0u64; self.columns.div_ceil(64)];
        (0..self.columns).for_each(|j| open[j / 64] |= 1 << (j % 64));
        let live: Vec<usize> = (0..self.cubes.len()).collect();
        let unit = vec![1; self.cubes.len()];
        for k in 1..=self.columns {
            let mut fewest = Search::new(self, &unit, k as u64 + 1, k, Vec::new());
            fewest.first_only = true;
            fewest.run(live.clone(), open.clone(), &mut Vec::new());
            if fewest.best.is_empty() {
                continue;
            }
            if std::env::var("QMDBG").is_ok() {
                eprintln!(
                    "  phase1 k {} nodes {}",
                    k,
                    NODES.load(std::sync::atomic::Ordering::Relaxed)
                );
            }
            let lits: Vec<u64> = self.cubes.iter().map(|c| c.literals().into()).collect();
            let limit = fewest.best.iter().map(|&r| lits[r]).sum();
            let mut shortest = Search::new(self, &lits, limit, k, fewest.best);
            shortest.run(live, open, &mut Vec::new());
            return shortest.best;
        }
        live // Not reached: one prime per on minterm always covers.
    }
}

/// The open columns of a search node and, for each, the live rows covering it.
struct View {
    cols: Vec<usize>,
    rows: BitRows,
}

/// The live rows of a search node and the open columns (positions in the [`View`]) each
/// covers, in compressed sparse form.
struct Incidence {
    rows: Vec<usize>,
    start: Vec<usize>,
    cols: Vec<usize>,
}

impl Incidence {
    fn cols_of(&self, i: usize) -> &[usize] {
        &self.cols[self.start[i]..self.start[i + 1]]
    }

    /// Lower bound on the weight still needed to cover the open columns, and each live row's
    /// reduced cost (indexed like `self.rows`). `weights` is indexed by row.
    ///
    /// The bound is Lagrangian: given a price `u_k >= 0` per open column, every cover costs at
    /// least `sum(u) + sum(min(0, c_r))`, where the reduced cost `c_r` of a row is its weight
    /// minus the prices of its columns. Prices start from a feasible dual solution and improve
    /// by subgradient steps, aiming at `budget`, the most a useful completion may cost.
    fn lower_bound(&self, view: &View, weights: &[u64], budget: f64) -> (f64, Vec<f64>) {
        let w: Vec<f64> = self.rows.iter().map(|&r| weights[r] as f64).collect();
        let reduced = |u: &[f64]| -> Vec<f64> {
            (0..w.len())
                .map(|i| w[i] - self.cols_of(i).iter().map(|&k| u[k]).sum::<f64>())
                .collect()
        };
        let value = |u: &[f64], c: &[f64]| {
            u.iter().sum::<f64>() + c.iter().map(|c| c.min(0.0)).sum::<f64>()
        };
        let mut u = greedy_prices(view, weights);
        let mut best = (value(&u, &reduced(&u)), u.clone());
        let (mut scale, mut stall) = (1.0, 0);
        for _ in 0..BOUND_STEPS {
            if best.0 > budget {
                break;
            }
            let c = reduced(&u);
            let lb = value(&u, &c);
            if lb > best.0 {
                best = (lb, u.clone());
                stall = 0;
            } else {
                stall += 1;
                if stall == 3 {
                    scale /= 2.0;
                    stall = 0;
                }
            }
            // Subgradient: 1 minus the number of negative-cost rows covering each column.
            let mut g = vec![1.0; u.len()];
            for i in (0..c.len()).filter(|&i| c[i] < 0.0) {
                self.cols_of(i).iter().for_each(|&k| g[k] -= 1.0);
            }
            let norm: f64 = g.iter().map(|x| x * x).sum();
            if norm == 0.0 {
                break;
            }
            let step = scale * (budget - lb).max(1.0) / norm;
            u.iter_mut()
                .zip(&g)
                .for_each(|(y, d)| *y = (*y + step * d).max(0.0));
        }
        let c = reduced(&best.1);
        (best.0, c)
    }
}

/// A feasible dual solution: raise each column's price, fewest rows first, until one of its
/// rows is fully paid.
fn greedy_prices(view: &View, weights: &[u64]) -> Vec<f64> {
    let n = view.cols.len();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&k| (count(view.rows.row(k)), k));
    let mut residual: Vec<f64> = weights.iter().map(|&w| w as f64).collect();
    let mut u = vec![0.0; n];
    for k in order {
        let rows = || ones(view.rows.row(k).iter().copied());
        let y = rows().map(|r| residual[r]).fold(f64::INFINITY, f64::min);
        if y > 0.0 && y.is_finite() {
            rows().for_each(|r| residual[r] -= y);
            u[k] = y;
        }
    }
    u
}

/// Branch-and-bound search for a cheapest cover under one weighting of the rows.
struct Search<'a> {
    table: &'a Table,
    /// Weight of each row.
    weights: &'a [u64],
    /// Only covers weighing less are of interest: the weight of `best` once there is one.
    limit: u64,
    /// Covers may use at most this many rows.
    max_rows: usize,
    /// Stop at the first cover found.
    first_only: bool,
    best: Vec<usize>,
}

impl<'a> Search<'a> {
    fn new(
        table: &'a Table,
        weights: &'a [u64],
        limit: u64,
        max_rows: usize,
        best: Vec<usize>,
    ) -> Search<'a> {
        Search {
            table,
            weights,
            limit,
            max_rows,
            first_only: false,
            best,
        }
    }

    /// Cover the `open` columns with `live` rows (sorted), extending `chosen`, which is left
    /// as it was found.
    fn run(&mut self, mut live: Vec<usize>, mut open: Vec<u64>, chosen: &mut Vec<usize>) {
        NODES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let depth = chosen.len();
        if let Some(view) = self.reduce(&mut live, &mut open, chosen) {
            self.branch(&live, &open, &view, chosen);
        }
        chosen.truncate(depth);
    }

    /// Take essential rows and drop dominated columns and rows until nothing changes.
    /// Returns the final view, or `None` when some open column can no longer be covered.
    fn reduce(
        &self,
        live: &mut Vec<usize>,
        open: &mut [u64],
        chosen: &mut Vec<usize>,
    ) -> Option<View> {
        loop {
            let view = self.view(live, open);
            let counts: Vec<u32> = (0..view.cols.len())
                .map(|k| count(view.rows.row(k)))
                .collect();
            if counts.contains(&0) {
                return None;
            }
            let essential: BTreeSet<usize> = (0..view.cols.len())
                .filter(|&k| counts[k] == 1)
                .flat_map(|k| ones(view.rows.row(k).iter().copied()))
                .collect();
            if !essential.is_empty() {
                for &r in &essential {
                    let cover = self.table.covers.row(r);
                    open.iter_mut().zip(cover).for_each(|(o, c)| *o &= !c);
                    chosen.push(r);
                }
                live.retain(|r| !essential.contains(r));
                continue;
            }
            if !drop_dominated_columns(&view, open) && !self.drop_dominated_rows(live, open) {
                return Some(view);
            }
        }
    }

    /// The open columns and the live rows covering each.
    fn view(&self, live: &[usize], open: &[u64]) -> View {
        let cols: Vec<usize> = ones(open.iter().copied()).collect();
        let mut at = vec![0; self.table.columns];
        cols.iter().enumerate().for_each(|(k, &j)| at[j] = k);
        let mut rows = BitRows::new(cols.len(), self.table.cubes.len());
        for &r in live {
            for j in ones(and(self.table.covers.row(r), open)) {
                rows.insert(at[j], r);
            }
        }
        View { cols, rows }
    }

    /// A row covering no more open columns than another row, at no lower weight, can be
    /// swapped for that row in any cover: remove it. Returns whether any row was removed.
    fn drop_dominated_rows(&self, live: &mut Vec<usize>, open: &[u64]) -> bool {
        let mut covers = BitRows::new(live.len(), self.table.columns);
        for (i, &r) in live.iter().enumerate() {
            let row = and(self.table.covers.row(r), open);
            covers
                .row_mut(i)
                .iter_mut()
                .zip(row)
                .for_each(|(d, w)| *d = w);
        }
        let sets = Subsets::new(&covers, live.len());
        let w = |i: usize| self.weights[live[i]];
        let dominated = |a: usize| {
            sets.count[a] == 0
                || (0..live.len()).any(|b| {
                    b != a
                        && w(b) <= w(a)
                        && sets.subset(a, b)
                        && (b < a || w(b) < w(a) || sets.count[a] != sets.count[b])
                })
        };
        let kept: Vec<usize> = (0..live.len())
            .filter(|&a| !dominated(a))
            .map(|a| live[a])
            .collect();
        let changed = kept.len() != live.len();
        *live = kept;
        changed
    }

    /// The live rows and the open columns each covers.
    fn incidence(&self, live: &[usize], view: &View, open: &[u64]) -> Incidence {
        let mut at = vec![0; self.table.columns];
        view.cols.iter().enumerate().for_each(|(k, &j)| at[j] = k);
        let mut inc = Incidence {
            rows: live.to_vec(),
            start: vec![0],
            cols: Vec::new(),
        };
        for &r in live {
            let cols = ones(and(self.table.covers.row(r), open)).map(|j| at[j]);
            inc.cols.extend(cols);
            inc.start.push(inc.cols.len());
        }
        inc
    }

    /// Check the node against the Lagrangian bounds on weight and, when rows are weighted
    /// otherwise, on their number. Returns `None` when no completion can be useful, else the
    /// live rows that still can be part of one and their reduced weights.
    fn bound(
        &self,
        live: &[usize],
        open: &[u64],
        view: &View,
        chosen: &[usize],
    ) -> Option<(Vec<usize>, Vec<f64>)> {
        let inc = self.incidence(live, view, open);
        let cost: u64 = chosen.iter().map(|&r| self.weights[r]).sum();
        // Weights are whole numbers; the epsilon absorbs rounding in the bound.
        let budget = (self.limit - cost - 1) as f64 + 1e-6;
        let (lb, reduced) = inc.lower_bound(view, self.weights, budget);
        // A row whose reduced weight alone lifts the bound past the budget is useless here.
        let mut useful: Vec<bool> = reduced.iter().map(|c| lb + c.max(0.0) <= budget).collect();
        if self.weights.iter().any(|&w| w != 1) {
            let budget = (self.max_rows - chosen.len()) as f64 + 1e-6;
            let unit = vec![1; self.weights.len()];
            let (lb_rows, reduced_rows) = inc.lower_bound(view, &unit, budget);
            if lb_rows > budget {
                return None;
            }
            for (u, c) in useful.iter_mut().zip(&reduced_rows) {
                *u &= lb_rows + c.max(0.0) <= budget;
            }
        }
        if lb > budget {
            return None;
        }
        let rows = live
            .iter()
            .zip(&useful)
            .filter(|(_, &u)| u)
            .map(|(&r, _)| r);
        Some((rows.collect(), reduced))
    }

    /// Record a complete cover, or prune, or split on the open column with fewest rows.
    fn branch(&mut self, live: &[usize], open: &[u64], view: &View, chosen: &mut Vec<usize>) {
        let cost: u64 = chosen.iter().map(|&r| self.weights[r]).sum();
        if cost >= self.limit || chosen.len() > self.max_rows {
            return;
        }
        if view.cols.is_empty() {
            self.limit = cost;
            self.best.clone_from(chosen);
            return;
        }
        let Some((useful, reduced)) = self.bound(live, open, view, chosen) else {
            return;
        };
        if useful.len() < live.len() {
            return self.run(useful, open.to_vec(), chosen);
        }
        let k = (0..view.cols.len())
            .min_by_key(|&k| (count(view.rows.row(k)), k))
            .unwrap_or(0);
        let mut candidates: Vec<(f64, usize)> = ones(view.rows.row(k).iter().copied())
            .map(|r| (live.binary_search(&r).map_or(0.0, |i| reduced[i]), r))
            .collect();
        candidates.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut rest = live.to_vec();
        for (_, r) in candidates {
            if self.first_only && !self.best.is_empty() {
                return;
            }
            rest.retain(|&x| x != r);
            let cover = self.table.covers.row(r);
            let next: Vec<u64> = open.iter().zip(cover).map(|(o, c)| o & !c).collect();
            chosen.push(r);
            self.run(rest.clone(), next, chosen);
            chosen.pop();
        }
    }
}

/// A column whose rows include all rows of another open column is covered whenever that one
/// is: stop tracking it. Returns whether any column was dropped.
fn drop_dominated_columns(view: &View, open: &mut [u64]) -> bool {
    let n = view.cols.len();
    let sets = Subsets::new(&view.rows, n);
    let mut changed = false;
    for a in 0..n {
        let dominated = (0..n)
            .any(|b| b != a && sets.subset(b, a) && (b < a || sets.count[a] != sets.count[b]));
        if dominated {
            let j = view.cols[a];
            open[j / 64] &= !(1 << (j % 64));
            changed = true;
        }
    }
    changed
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn cube(care: u32, value: u32) -> Cube {
        Cube { care, value }
    }

    /// Whether `cover` is true on minterm `m`.
    fn covered(cover: &[Cube], m: u32) -> bool {
        cover.iter().any(|c| c.contains(m))
    }

    #[test]
    fn xor_needs_two_cubes() {
        assert_eq!(minimize(2, &[1, 2], &[]), vec![cube(3, 1), cube(3, 2)]);
    }

    #[test]
    fn majority_needs_three_cubes() {
        assert_eq!(
            minimize(3, &[3, 5, 6, 7], &[]),
            vec![cube(3, 3), cube(5, 5), cube(6, 6)]
        );
    }

    #[test]
    fn constants() {
        assert_eq!(minimize(3, &[], &[]), vec![]);
        assert_eq!(minimize(3, &[], &[0, 1, 2, 3, 4, 5, 6, 7]), vec![]);
        assert_eq!(
            minimize(3, &(0..8).collect::<Vec<_>>(), &[]),
            vec![cube(0, 0)]
        );
        assert_eq!(minimize(3, &[5], &[0, 1, 2, 3, 4, 6, 7]), vec![cube(0, 0)]);
        assert_eq!(minimize(0, &[0], &[]), vec![cube(0, 0)]);
    }

    #[test]
    fn dont_cares_grow_cubes() {
        // on = {0b011}, dc = {0b111}: the cube drops variable 2.
        assert_eq!(minimize(3, &[3], &[7]), vec![cube(3, 3)]);
        // on wins over dc for the same minterm; bits above n are ignored.
        assert_eq!(minimize(2, &[1, 1], &[1]), vec![cube(3, 1)]);
        assert_eq!(minimize(2, &[5], &[]), vec![cube(3, 1)]);
    }

    #[test]
    fn cyclic_core_takes_three_of_six_primes() {
        let primes = prime_implicants(7, &[0, 1, 2, 5, 6, 7], &[]);
        assert_eq!(primes.len(), 6);
        let cover = minimize(3, &[0, 1, 2, 5, 6, 7], &[]);
        assert_eq!(cover.len(), 3);
    }

    #[test]
    fn parity_has_no_merges() {
        let odd: Vec<u32> = (0..16u32).filter(|m| m.count_ones() % 2 == 1).collect();
        let cover = minimize(4, &odd, &[]);
        assert_eq!(cover, odd.iter().map(|&m| cube(15, m)).collect::<Vec<_>>());
    }

    #[test]
    fn output_does_not_depend_on_input_order() {
        let on = [9, 3, 14, 1, 7, 12, 0, 5];
        let mut rev = on;
        rev.reverse();
        assert_eq!(minimize(4, &on, &[2, 10]), minimize(4, &rev, &[10, 2, 2]));
    }

    /// A small deterministic pseudo-random sequence (64-bit LCG, high bits).
    fn lcg(seed: &mut u64) -> u32 {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*seed >> 33) as u32
    }

    #[test]
    fn eight_variables_stay_exact_and_quick() {
        let mut seed = 1;
        for _ in 0..40 {
            let (mut on, mut dc) = (Vec::new(), Vec::new());
            for m in 0..256 {
                match lcg(&mut seed) % 4 {
                    0 | 1 => on.push(m),
                    2 => dc.push(m),
                    _ => {}
                }
            }
            let cover = minimize(8, &on, &dc);
            for m in 0..256 {
                let want = on.contains(&m) || (dc.contains(&m) && covered(&cover, m));
                assert_eq!(covered(&cover, m), want, "minterm {m}");
            }
        }
    }

    /// Primes by definition: implicants (no off minterm) not inside a larger implicant.
    fn brute_primes(n: usize, off: &[u32]) -> Vec<Cube> {
        let mask = var_mask(n);
        let implicant = |c: Cube| !off.iter().any(|&m| c.contains(m));
        let mut primes = Vec::new();
        for care in 0..=mask {
            for value in 0..=mask {
                let c = cube(care, value);
                if value & !care == 0
                    && implicant(c)
                    && !bits(care).any(|b| implicant(cube(care & !b, value & !b)))
                {
                    primes.push(c);
                }
            }
        }
        primes.sort();
        primes
    }

    /// Minimum (cubes, literals) of a cover of `on` by a subset of `primes`.
    fn brute_min_cost(primes: &[Cube], on: &[u32]) -> (usize, u32) {
        let cov: Vec<u64> = primes
            .iter()
            .map(|p| {
                (0..on.len())
                    .filter(|&j| p.contains(on[j]))
                    .map(|j| 1u64 << j)
                    .sum()
            })
            .collect();
        let all: u64 = (0..on.len()).map(|j| 1u64 << j).sum();
        let mut best = (usize::MAX, u32::MAX);
        for set in 0u32..1 << primes.len() {
            let picked = (0..primes.len()).filter(|&i| set >> i & 1 == 1);
            let hit: u64 = picked.clone().fold(0, |acc, i| acc | cov[i]);
            if hit == all {
                let cost = (
                    set.count_ones() as usize,
                    picked.map(|i| primes[i].literals()).sum(),
                );
                best = best.min(cost);
            }
        }
        best
    }

    proptest! {
        #[test]
        fn cover_is_correct_and_minimum(n in 1usize..=6, kinds in prop::collection::vec(0u8..3, 64)) {
            let size = 1u32 << n;
            let kind = |m: u32| kinds[m as usize];
            let on: Vec<u32> = (0..size).filter(|&m| kind(m) == 0).collect();
            let dc: Vec<u32> = (0..size).filter(|&m| kind(m) == 1).collect();
            let off: Vec<u32> = (0..size).filter(|&m| kind(m) == 2).collect();
            let cover = minimize(n, &on, &dc);
            for &m in &on {
                prop_assert!(covered(&cover, m), "on minterm {} uncovered", m);
            }
            for &m in &off {
                prop_assert!(!covered(&cover, m), "off minterm {} covered", m);
            }
            let primes = prime_implicants(var_mask(n), &on, &dc);
            prop_assert_eq!(&primes, &brute_primes(n, &off));
            for c in &cover {
                prop_assert!(primes.contains(c));
            }
            let useful: Vec<Cube> = primes
                .into_iter()
                .filter(|p| on.iter().any(|&m| p.contains(m)))
                .collect();
            if useful.len() <= 16 && !on.is_empty() {
                let got = (cover.len(), cover.iter().map(Cube::literals).sum());
                prop_assert_eq!(got, brute_min_cost(&useful, &on));
            }
        }
    }
}
#[doc(hidden)]
pub fn __timing() {
    let mut seed: u64 = 7;
    let mut lcg = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) as u32
    };
    for (n, on_pct, dc_pct) in [(8, 75, 10)] {
        let mut worst = std::time::Duration::ZERO;
        let mut tot = std::time::Duration::ZERO;
        for _ in 0..4 {
            let (mut on, mut dc) = (Vec::new(), Vec::new());
            for m in 0..1u32 << n {
                let x = lcg() % 100;
                if x < on_pct {
                    on.push(m)
                } else if x < on_pct + dc_pct {
                    dc.push(m)
                }
            }
            let t = std::time::Instant::now();
            let c = minimize(n, &on, &dc);
            let e = t.elapsed();
            worst = worst.max(e);
            tot += e;
            eprintln!(
                "{:?} {} nodes {}",
                e,
                c.len(),
                NODES.swap(0, std::sync::atomic::Ordering::Relaxed)
            );
        }
        eprintln!("random n={n} on={on_pct}% dc={dc_pct}%: worst {worst:?} total {tot:?}");
    }
    for n in [8usize, 10] {
        let mut worst = std::time::Duration::ZERO;
        let mut tot = std::time::Duration::ZERO;
        let mut maxc = 0;
        for _ in 0..20 {
            let k = 2 + lcg() % 6;
            let mask = (1u32 << n) - 1;
            let cubes: Vec<Cube> = (0..k)
                .map(|_| {
                    let care = lcg() & lcg() & mask | (1 << (lcg() % n as u32));
                    Cube {
                        care,
                        value: lcg() & care,
                    }
                })
                .collect();
            let (mut on, mut dc) = (Vec::new(), Vec::new());
            for m in 0..1u32 << n {
                if cubes.iter().any(|c| c.contains(m)) {
                    on.push(m)
                } else if lcg() % 10 == 0 {
                    dc.push(m)
                }
            }
            let t = std::time::Instant::now();
            let c = minimize(n, &on, &dc);
            let e = t.elapsed();
            worst = worst.max(e);
            tot += e;
            maxc = maxc.max(c.len());
        }
        eprintln!("structured n={n}: worst {worst:?} total {tot:?} max cubes {maxc}");
    }
}
