//! What every property test shares: a stated seed, so that every run checks the same cases
//! (set `PROPTEST_RNG_SEED`, and `PROPTEST_CASES`, to explore others), and how the readers
//! count lines, to check the line an error names.

use proptest::test_runner::{Config, RngSeed};

/// `cases` cases drawn from `seed`, no failure file written (proptest prints the failing
/// case, and the seed reproduces it).
pub fn config(cases: u32, seed: u64) -> Config {
    seeded(
        Config {
            cases,
            failure_persistence: None,
            ..Config::default()
        },
        seed,
    )
}

/// `config` with its cases drawn from `seed`, unless `PROPTEST_RNG_SEED` is set; with
/// `PROPTEST_CASES` set, its number of cases is that one.
pub fn seeded(mut config: Config, seed: u64) -> Config {
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(seed);
    }
    if std::env::var_os("PROPTEST_CASES").is_some() {
        config.cases = Config::default().cases;
    }
    config
}

/// Lines of `bytes` as the readers count them (LF, CRLF or a lone CR end a line).
#[allow(dead_code)] // the readers' tests use it; the scenario tests do not
pub fn line_count(bytes: &[u8]) -> usize {
    let breaks = bytes
        .iter()
        .enumerate()
        .filter(|&(i, &b)| b == b'\n' || (b == b'\r' && bytes.get(i + 1) != Some(&b'\n')))
        .count();
    breaks + 1
}

/// The line an error names, if it starts with one (`line 12...`).
#[allow(dead_code)] // as `line_count`
pub fn named_line(message: &str) -> Option<usize> {
    let rest = message.strip_prefix("line ")?;
    let end = rest.find(|c: char| !c.is_ascii_digit())?;
    rest[..end].parse().ok()
}
