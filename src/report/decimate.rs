//! Thinning long series for plotting without losing their extremes.

/// At most about `max_points` points of a series `(t, y)` ordered by `t`, keeping, in each
/// of `max_points / 2` equal runs of consecutive points, the lowest and highest `y` (in
/// their original order), plus the first and last point of the series.
///
/// A line through the result has the same envelope as one through all points, which a
/// plain stride would not guarantee (a one-sample spike could vanish). Series no longer
/// than `max_points` are returned as they are. Non-finite `y` values are dropped.
///
/// # Example
///
/// ```
/// use armdyn::report::decimate_min_max;
///
/// let series: Vec<(f64, f64)> = (0..10_000)
///     .map(|i| (i as f64, if i == 4321 { 100.0 } else { 0.0 }))
///     .collect();
/// let thin = decimate_min_max(&series, 200);
/// assert!(thin.len() <= 202);
/// assert!(thin.contains(&(4321.0, 100.0))); // the spike survives
/// assert_eq!(thin.last(), Some(&(9999.0, 0.0)));
/// ```
pub fn decimate_min_max(series: &[(f64, f64)], max_points: usize) -> Vec<(f64, f64)> {
    let finite: Vec<(f64, f64)> = series
        .iter()
        .copied()
        .filter(|(t, y)| t.is_finite() && y.is_finite())
        .collect();
    let n = finite.len();
    if n <= max_points.max(2) {
        return finite;
    }
    let buckets = (max_points / 2).max(1);
    let mut out = Vec::with_capacity(2 * buckets + 2);
    out.push(finite[0]);
    let mut last_index = 0;
    for b in 0..buckets {
        let start = b * n / buckets;
        let end = ((b + 1) * n / buckets).max(start + 1);
        let (mut lo, mut hi) = (start, start);
        for i in start..end {
            if finite[i].1 < finite[lo].1 {
                lo = i;
            }
            if finite[i].1 > finite[hi].1 {
                hi = i;
            }
        }
        let (a, b) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        for i in [a, b] {
            if i > last_index {
                out.push(finite[i]);
                last_index = i;
            }
        }
    }
    if last_index != n - 1 {
        out.push(finite[n - 1]);
    }
    out
}

/// At most about `max_points` items of `items`, by taking every `k`-th one, always keeping
/// the first and the last. For curves that are not functions of one axis (a path in x-y),
/// where min/max per run has no meaning.
pub fn decimate_stride<T: Copy>(items: &[T], max_points: usize) -> Vec<T> {
    let n = items.len();
    if n <= max_points.max(2) {
        return items.to_vec();
    }
    let k = n.div_ceil(max_points.max(2) - 1);
    let mut out: Vec<T> = items.iter().step_by(k).copied().collect();
    if (n - 1) / k * k != n - 1 {
        out.push(items[n - 1]);
    }
    out
}
