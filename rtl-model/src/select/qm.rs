//! Exact two-level minimization (Quine-McCluskey) of the select-logic truth tables.
//!
//! The thesis derives the select equations of §2.3.3-2.3.5 from hand-made Karnaugh maps. This
//! module is the machine check: [`minimize`] computes a minimum sum-of-products cover of a
//! truth table with don't-cares, so the printed equations can be compared with a true optimum.
//!
//! The prime implicants of on ∪ dc come from the classic tabular method: repeatedly merge
//! cubes that differ in one literal. A cheapest set of primes covering the on-set is then
//! found exactly by branch and bound: essential primes and row/column dominance shrink the
//! table, a Lagrangian lower bound prunes and orders the branches. Every container is ordered
//! and every tie broken by index, so the result is fully deterministic.

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
/// Intended for `n <= 12`; never panics. Exact covering is exponential in the worst case:
/// structured functions of up to 8 variables take milliseconds, but random ones with a dense
/// on-set (75% and more of the minterms) can take seconds.
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

/// Whether `a ⊆ b`.
fn subset(a: &[u64], b: &[u64]) -> bool {
    a.iter().zip(b).all(|(x, y)| x & !y == 0)
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

    fn insert(&mut self, i: usize, bit: usize) {
        self.data[i * self.words + bit / 64] |= 1 << (bit % 64);
    }

    fn ones(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        ones(self.row(i).iter().copied())
    }

    fn counts(&self, n: usize) -> Vec<u32> {
        (0..n)
            .map(|i| self.row(i).iter().map(|w| w.count_ones()).sum())
            .collect()
    }
}

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
        let none = Prices::default();
        for k in 1..=self.columns {
            let mut fewest = Search::new(self, &unit, k as u64 + 1, k, Vec::new());
            fewest.first_only = true;
            fewest.run(live.clone(), open.clone(), &mut Vec::new(), &none);
            if fewest.best.is_empty() {
                continue;
            }
            let lits: Vec<u64> = self.cubes.iter().map(|c| c.literals().into()).collect();
            let limit = fewest.best.iter().map(|&r| lits[r]).sum();
            let mut shortest = Search::new(self, &lits, limit, k, fewest.best);
            shortest.count_bound = true;
            shortest.run(live, open, &mut Vec::new(), &none);
            return shortest.best;
        }
        live // Not reached: one prime per on minterm always covers.
    }
}

/// The table at one search node: the open columns and live rows, and which covers which,
/// both ways round and by position in `cols` and `rows`.
struct View {
    /// Open column indices, ascending.
    cols: Vec<usize>,
    /// Live row indices, ascending.
    rows: Vec<usize>,
    /// For each column, the rows covering it.
    col_rows: BitRows,
    /// For each row, the columns it covers.
    row_cols: BitRows,
    /// Number of columns of the whole table.
    width: usize,
}

impl View {
    fn new(table: &Table, live: &[usize], open: &[u64]) -> View {
        let cols: Vec<usize> = ones(open.iter().copied()).collect();
        let mut at = vec![0; table.columns];
        cols.iter().enumerate().for_each(|(k, &j)| at[j] = k);
        let mut col_rows = BitRows::new(cols.len(), live.len());
        let mut row_cols = BitRows::new(live.len(), cols.len());
        for (i, &r) in live.iter().enumerate() {
            for j in ones(and(table.covers.row(r), open)) {
                col_rows.insert(at[j], i);
                row_cols.insert(i, at[j]);
            }
        }
        View {
            cols,
            rows: live.to_vec(),
            col_rows,
            row_cols,
            width: table.columns,
        }
    }

    /// Columns covered whenever another column is, because each row covering the other
    /// covers them too (of equal columns all but the first). Returns column indices.
    fn implied_columns(&self) -> Vec<usize> {
        let n = self.cols.len();
        let row_size = self.row_cols.counts(self.rows.len());
        let col_size = self.col_rows.counts(n);
        let mut implied = vec![false; n];
        for b in 0..n {
            // Columns whose rows include b's rows are all covered by b's smallest row.
            let Some(pivot) = self.col_rows.ones(b).min_by_key(|&i| (row_size[i], i)) else {
                continue;
            };
            for a in self.row_cols.ones(pivot) {
                if a != b
                    && (b < a || col_size[b] < col_size[a])
                    && subset(self.col_rows.row(b), self.col_rows.row(a))
                {
                    implied[a] = true;
                }
            }
        }
        (0..n)
            .filter(|&a| implied[a])
            .map(|a| self.cols[a])
            .collect()
    }

    /// For each row, whether another row covers all its columns at no higher `weight` (of
    /// equal rows all but the first), or it covers no column: such rows can be dropped.
    fn dominated_rows(&self, weight: impl Fn(usize) -> u64) -> Vec<bool> {
        let m = self.rows.len();
        let row_size = self.row_cols.counts(m);
        let col_size = self.col_rows.counts(self.cols.len());
        let w: Vec<u64> = self.rows.iter().map(|&r| weight(r)).collect();
        let dominated = |a: usize| {
            // Rows covering all of a's columns include a's column with fewest rows.
            let Some(pivot) = self.row_cols.ones(a).min_by_key(|&k| (col_size[k], k)) else {
                return true;
            };
            self.col_rows.ones(pivot).any(|b| {
                b != a
                    && w[b] <= w[a]
                    && (b < a || w[b] < w[a] || row_size[a] < row_size[b])
                    && subset(self.row_cols.row(a), self.row_cols.row(b))
            })
        };
        (0..m).map(dominated).collect()
    }

    /// Lagrangian lower bound on the weight still needed to cover the open columns, with
    /// row `i` weighing `weights[i]`.
    ///
    /// Given a price `u_k >= 0` per column, every cover weighs at least
    /// `sum(u) + sum(min(0, c_r))`, where the reduced weight `c_r` of a row is its weight
    /// minus the prices of its columns. Prices start from the better of a feasible dual
    /// solution and the `warm` prices (by column index; may be empty), then improve by
    /// subgradient steps aiming at `budget`, the most a useful completion may weigh.
    fn lower_bound(&self, weights: &[f64], budget: f64, warm: &[f64]) -> Bound {
        let mut start = vec![0];
        let mut cols = Vec::new();
        for i in 0..self.rows.len() {
            cols.extend(self.row_cols.ones(i));
            start.push(cols.len());
        }
        let cols_of = |i: usize| &cols[start[i]..start[i + 1]];
        let reduced = |u: &[f64]| -> Vec<f64> {
            let price = |i: usize| cols_of(i).iter().map(|&k| u[k]).sum::<f64>();
            (0..weights.len()).map(|i| weights[i] - price(i)).collect()
        };
        let value = |u: &[f64], c: &[f64]| {
            u.iter().sum::<f64>() + c.iter().map(|c| c.min(0.0)).sum::<f64>()
        };
        let mut u = self.greedy_prices(weights);
        let mut best = (value(&u, &reduced(&u)), u.clone());
        if !warm.is_empty() {
            let w: Vec<f64> = self.cols.iter().map(|&j| warm[j]).collect();
            let v = value(&w, &reduced(&w));
            if v > best.0 {
                best = (v, w.clone());
                u = w;
            }
        }
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
                cols_of(i).iter().for_each(|&k| g[k] -= 1.0);
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
        let mut prices = vec![0.0; self.width];
        self.cols
            .iter()
            .zip(&best.1)
            .for_each(|(&j, &y)| prices[j] = y);
        Bound {
            value: best.0,
            reduced: reduced(&best.1),
            prices,
        }
    }

    /// A feasible dual solution: raise each column's price, fewest rows first, until one of
    /// its rows is fully paid.
    fn greedy_prices(&self, weights: &[f64]) -> Vec<f64> {
        let n = self.cols.len();
        let size = self.col_rows.counts(n);
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by_key(|&k| (size[k], k));
        let mut residual = weights.to_vec();
        let mut u = vec![0.0; n];
        for k in order {
            let y = (self.col_rows.ones(k))
                .map(|i| residual[i])
                .fold(f64::INFINITY, f64::min);
            if y > 0.0 && y.is_finite() {
                self.col_rows.ones(k).for_each(|i| residual[i] -= y);
                u[k] = y;
            }
        }
        u
    }
}

/// Subgradient steps per lower bound.
const BOUND_STEPS: usize = 60;

/// A Lagrangian lower bound at one search node.
struct Bound {
    value: f64,
    /// Reduced weight of each row (by position in the view).
    reduced: Vec<f64>,
    /// The column prices that give it, by column index.
    prices: Vec<f64>,
}

impl Bound {
    /// Which rows can be part of a completion weighing at most `budget`: forcing a row in
    /// adds its reduced weight to the bound.
    fn useful(&self, budget: f64) -> impl Iterator<Item = bool> + '_ {
        (self.reduced.iter()).map(move |c| self.value + c.max(0.0) <= budget)
    }
}

/// Column prices of a node's bounds, handed to its children to start theirs from: a child's
/// table is part of its parent's, so the prices stay good. Empty when there are none yet.
#[derive(Default)]
struct Prices {
    weight: Vec<f64>,
    rows: Vec<f64>,
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
    /// Also bound the number of rows, not only the weight.
    count_bound: bool,
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
            count_bound: false,
            first_only: false,
            best,
        }
    }

    /// Cover the `open` columns with `live` rows (ascending), extending `chosen`, which is
    /// left as it was found.
    fn run(
        &mut self,
        mut live: Vec<usize>,
        mut open: Vec<u64>,
        chosen: &mut Vec<usize>,
        warm: &Prices,
    ) {
        let depth = chosen.len();
        let mut narrowed: Option<Prices> = None;
        while let Some(view) = self.reduce(&mut live, &mut open, chosen) {
            let warm = narrowed.as_ref().unwrap_or(warm);
            let Some((rows, prices)) = self.branch(&view, &open, chosen, warm) else {
                break;
            };
            live = rows;
            narrowed = Some(prices);
        }
        chosen.truncate(depth);
    }

    /// Take essential rows, close implied columns and drop dominated rows until nothing
    /// changes. Returns the final view, or `None` when some column can no longer be covered.
    fn reduce(
        &self,
        live: &mut Vec<usize>,
        open: &mut [u64],
        chosen: &mut Vec<usize>,
    ) -> Option<View> {
        loop {
            let view = View::new(self.table, live, open);
            let size = view.col_rows.counts(view.cols.len());
            if size.contains(&0) {
                return None;
            }
            let essential: BTreeSet<usize> = (0..view.cols.len())
                .filter(|&k| size[k] == 1)
                .flat_map(|k| view.col_rows.ones(k))
                .map(|i| view.rows[i])
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
            let implied = view.implied_columns();
            if !implied.is_empty() {
                implied
                    .iter()
                    .for_each(|j| open[j / 64] &= !(1 << (j % 64)));
                continue;
            }
            let dominated = view.dominated_rows(|r| self.weights[r]);
            if !dominated.contains(&true) {
                return Some(view);
            }
            live.clear();
            live.extend(
                (0..view.rows.len())
                    .filter(|&i| !dominated[i])
                    .map(|i| view.rows[i]),
            );
        }
    }

    /// Check the node against the Lagrangian bounds on weight and, with `count_bound`, on
    /// the number of rows. Returns `None` when no completion can be useful, else which rows
    /// can still be part of one, the reduced weights (both by row position) and the prices
    /// for the children.
    fn bound(
        &self,
        view: &View,
        chosen: &[usize],
        warm: &Prices,
    ) -> Option<(Vec<bool>, Vec<f64>, Prices)> {
        let cost: u64 = chosen.iter().map(|&r| self.weights[r]).sum();
        let weights: Vec<f64> = view.rows.iter().map(|&r| self.weights[r] as f64).collect();
        // Weights are whole numbers; the epsilon absorbs rounding in the bound.
        let budget = (self.limit - cost - 1) as f64 + 1e-6;
        let by_weight = view.lower_bound(&weights, budget, &warm.weight);
        if by_weight.value > budget {
            return None;
        }
        let mut useful: Vec<bool> = by_weight.useful(budget).collect();
        let mut prices = Prices {
            weight: by_weight.prices,
            rows: Vec::new(),
        };
        if self.count_bound {
            let budget = (self.max_rows - chosen.len()) as f64 + 1e-6;
            let by_rows = view.lower_bound(&vec![1.0; weights.len()], budget, &warm.rows);
            if by_rows.value > budget {
                return None;
            }
            (useful.iter_mut())
                .zip(by_rows.useful(budget))
                .for_each(|(u, v)| *u &= v);
            prices.rows = by_rows.prices;
        }
        Some((useful, by_weight.reduced, prices))
    }

    /// Record a complete cover, or prune, or split on the column with fewest rows: one
    /// branch per row covering it, cheapest reduced weight first, each excluding the rows
    /// tried before it. When the bound shows some rows useless, instead returns the others
    /// (and the prices found), to reduce the node again.
    fn branch(
        &mut self,
        view: &View,
        open: &[u64],
        chosen: &mut Vec<usize>,
        warm: &Prices,
    ) -> Option<(Vec<usize>, Prices)> {
        let cost: u64 = chosen.iter().map(|&r| self.weights[r]).sum();
        if cost >= self.limit || chosen.len() > self.max_rows {
            return None;
        }
        if view.cols.is_empty() {
            self.limit = cost;
            self.best.clone_from(chosen);
            return None;
        }
        let (useful, reduced, prices) = self.bound(view, chosen, warm)?;
        if useful.contains(&false) {
            let live = (0..view.rows.len()).filter(|&i| useful[i]);
            return Some((live.map(|i| view.rows[i]).collect(), prices));
        }
        let size = view.col_rows.counts(view.cols.len());
        let k = (0..size.len()).min_by_key(|&k| (size[k], k)).unwrap_or(0);
        let mut candidates: Vec<usize> = view.col_rows.ones(k).collect();
        candidates.sort_by(|&a, &b| reduced[a].total_cmp(&reduced[b]).then(a.cmp(&b)));
        let mut rest = view.rows.clone();
        for i in candidates {
            if self.first_only && !self.best.is_empty() {
                break;
            }
            let r = view.rows[i];
            rest.retain(|&x| x != r);
            let cover = self.table.covers.row(r);
            let next: Vec<u64> = open.iter().zip(cover).map(|(o, c)| o & !c).collect();
            chosen.push(r);
            self.run(rest.clone(), next, chosen, &prices);
            chosen.pop();
        }
        None
    }
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
