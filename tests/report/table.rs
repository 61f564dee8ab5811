//! Tests of `armdyn::report::table`: the Markdown table: ragged rows, escaping and Unicode widths,
//! explicit alignment, an empty table.

use armdyn::report::table::*;

#[test]
fn ragged_rows_escaping_and_unicode() {
    let t = Table::new(["a", "b"])
        .row(["x|y", "1", "extra"])
        .row(["é", "-"]);
    assert_eq!(
        t.markdown(),
        "| a    |   b |       |\n\
         | :--- | --: | :---- |\n\
         | x\\|y |   1 | extra |\n\
         | é    |   - |       |\n"
    );
    assert_eq!(t.len(), 2);
}

#[test]
fn explicit_alignment_wins() {
    let t = Table::new(["n"]).row(["1"]).align(0, Align::Left);
    assert_eq!(t.plain(), "n\n-\n1\n");
    assert_eq!(t.to_string(), t.plain());
    let t = Table::new(["name", "value"]).row(["k", "2"]);
    assert_eq!(t.plain(), "name  value\n----  -----\nk         2\n");
}

#[test]
fn empty_table() {
    let t = Table::new(["only"]);
    assert!(t.is_empty());
    assert_eq!(t.markdown(), "| only |\n| :--- |\n");
}
