//! Sorting (and keying) through as few instantiations of std's generic code as possible.
//!
//! Every `sort_by` with its own closure, and every element type, is a separate copy of std's
//! driftsort or ipnsort in the `.wasm` (3–9 KB each; nine of them were an eighth of the module).
//! The crate sorts only three kinds of things — `f64` keys, indices and index pairs — and does so
//! through two instantiations: [`argsort`] sorts `(f64, usize)` pairs, and indices and index
//! pairs both become `u64` keys for [`sort_keys`]. [`pair_key`] also keys the
//! simulation's hash maps, which thereby share one `HashMap<u64, usize>` instantiation.

/// The permutation that sorts `keys` ascending by [`f64::total_cmp`]; equal keys keep their
/// index order (a stable order, from an unstable sort over `(key, index)` pairs, which are all
/// distinct).
pub fn argsort(keys: &[f64]) -> Vec<usize> {
    let mut pairs: Vec<(f64, usize)> = keys.iter().copied().zip(0..).collect();
    pairs.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    pairs.into_iter().map(|(_, i)| i).collect()
}

/// Sorts `v` ascending by [`f64::total_cmp`].
pub fn sort_f64(v: &mut Vec<f64>) {
    let sorted: Vec<f64> = argsort(v).into_iter().map(|i| v[i]).collect();
    *v = sorted;
}

/// The one integer sort, ascending. Shared by [`sort_dedup`], [`sort_pairs`] and
/// [`sort_dedup_pairs`] so that std's unstable sort is instantiated once for all of them (each
/// instantiation costs 3–7 KB of the `.wasm`).
fn sort_keys(keys: &mut [u64]) {
    keys.sort_unstable();
}

/// [`sort_keys`], then repeats removed.
fn sort_dedup_keys(keys: &mut Vec<u64>) {
    sort_keys(keys);
    keys.dedup();
}

/// Sorts indices ascending and removes repeats.
pub fn sort_dedup(v: &mut Vec<usize>) {
    let mut keys: Vec<u64> = v.iter().map(|&i| i as u64).collect();
    sort_dedup_keys(&mut keys);
    v.clear();
    v.extend(keys.into_iter().map(|k| k as usize));
}

/// An index pair as one `u64`, `i · 2³² + j`, which orders like the pair. Both indices must be
/// below 2³² (always so on wasm32; natively, more vertices or segments than that would not fit
/// in memory anyway).
pub fn pair_key(i: usize, j: usize) -> u64 {
    assert!((i | j) as u64 <= LOW, "index pair beyond 2³²");
    (i as u64) << 32 | j as u64
}

/// The low half of a [`pair_key`]: `j`.
const LOW: u64 = u32::MAX as u64;

/// Sorts index pairs lexicographically (as [`pair_key`]s), repeats kept.
pub fn sort_pairs(v: &mut [(usize, usize)]) {
    let mut keys: Vec<u64> = v.iter().map(|&(i, j)| pair_key(i, j)).collect();
    sort_keys(&mut keys);
    for (pair, k) in v.iter_mut().zip(keys) {
        *pair = unpair(k);
    }
}

/// Sorts index pairs lexicographically and removes repeats (as [`pair_key`]s).
pub fn sort_dedup_pairs(v: &mut Vec<(usize, usize)>) {
    let mut keys: Vec<u64> = v.iter().map(|&(i, j)| pair_key(i, j)).collect();
    sort_dedup_keys(&mut keys);
    v.clear();
    v.extend(keys.into_iter().map(unpair));
}

/// The pair `(i, j)` of a [`pair_key`].
pub fn unpair(k: u64) -> (usize, usize) {
    ((k >> 32) as usize, (k & LOW) as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn argsort_is_stable_and_orders_by_total_cmp() {
        let keys = [3.0, -0.0, 1.0, 0.0, 1.0, f64::NEG_INFINITY, -1.0];
        let got = argsort(&keys);
        // total_cmp puts -0.0 before 0.0; the two 1.0 keep their index order.
        assert_eq!(got, vec![5, 6, 1, 3, 2, 4, 0], "wanted the stable total order");
        let mut v = keys.to_vec();
        sort_f64(&mut v);
        let mut want = keys.to_vec();
        want.sort_by(f64::total_cmp);
        assert_eq!(v.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), want.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
    }

    #[test]
    fn argsort_is_std_stable_sort_by_total_cmp() {
        let pool = [-1.5, -0.0, 0.0, 2.0, f64::NAN, -f64::NAN, f64::INFINITY, -f64::INFINITY, 1e-310, -1e-310, 3.25];
        let mut state = 12345u64;
        for n in 0..200 {
            let keys: Vec<f64> = (0..n)
                .map(|_| {
                    state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    pool[(state >> 33) as usize % pool.len()]
                })
                .collect();
            let mut want: Vec<usize> = (0..n).collect();
            want.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
            assert_eq!(argsort(&keys), want, "{keys:?}");
        }
    }

    #[test]
    fn dedup_helpers_sort_and_remove_repeats() {
        let mut v = vec![4, 1, 4, 0, 1];
        sort_dedup(&mut v);
        assert_eq!(v, vec![0, 1, 4]);
        let mut p = vec![(2, 3), (0, 5), (2, 3), (0, 1), (1, 0), (0, u32::MAX as usize)];
        let mut q = p.clone();
        sort_pairs(&mut q);
        assert_eq!(q, vec![(0, 1), (0, 5), (0, u32::MAX as usize), (1, 0), (2, 3), (2, 3)]);
        sort_dedup_pairs(&mut p);
        assert_eq!(p, vec![(0, 1), (0, 5), (0, u32::MAX as usize), (1, 0), (2, 3)]);
    }
}
