//! Tests of `armdyn::sim::torque_history`: the torque history CSV reader: rows in header order, a
//! byte-order mark and CRLF, errors with their line and column.

use armdyn::csv_text::CsvError;
use armdyn::model::JointVector;
use armdyn::sim::torque_history::*;

fn read(text: &str) -> Result<TorqueHistory<4>, CsvError> {
    TorqueHistory::from_csv_reader(text.as_bytes())
}

const GOOD: &str = "t,tau1,tau2,tau3,tau4\n0,1,2,3,4\n0.5,5,6,7,8\n";

#[test]
fn reads_rows_in_header_order() {
    let h = read("tau4, t ,tau3,tau2,tau1\n4,0,3,2,1\n\n8,0.5,7,6,5\n").unwrap();
    assert_eq!(h.times(), &[0.0, 0.5]);
    assert_eq!(h.torques()[0], JointVector::<4>::new(1.0, 2.0, 3.0, 4.0));
    assert_eq!(h.torques()[1], JointVector::<4>::new(5.0, 6.0, 7.0, 8.0));
}

#[test]
fn byte_order_mark_and_crlf_are_accepted() {
    let plain = read(GOOD).unwrap();
    let crlf = GOOD.replace('\n', "\r\n");
    assert_eq!(read(&crlf).unwrap(), plain);
    assert_eq!(read(&format!("\u{feff}{GOOD}")).unwrap(), plain);
    assert_eq!(read(&format!("\u{feff}{crlf}")).unwrap(), plain);
    // Lines are still counted right.
    let bad = "\u{feff}t,tau1,tau2,tau3,tau4\r\n0,1,2,3,4\r\n\r\n0.5,5,x,7,8\r\n";
    assert_eq!(
        read(bad).unwrap_err().to_string(),
        "line 4, column 3 (`tau2`): `x` is not a number"
    );
}

#[test]
fn errors_name_line_and_column() {
    let cases = [
        (
            "",
            "line 1: the input ends before the header (expected `t,tau1,tau2,tau3,tau4` (in any order))",
        ),
        (
            "\n t,tau1,tau2,tau3\n0,0,0,0\n",
            "line 2: missing column `tau4`",
        ),
        (
            "t,tau1,tau2,tau3,tau4,x\n",
            "line 1: the header must be exactly the columns `t,tau1,tau2,tau3,tau4`",
        ),
        (
            "t,tau1,tau2,tau3,tau4\n",
            "0 data row(s) after the header; the file needs at least 1",
        ),
        (
            "t,tau1,tau2,tau3,tau4\n0,0,0,0\n",
            "line 2, column 5: missing column `tau4` (expected 5 columns",
        ),
        (
            "t,tau1,tau2,tau3,tau4\n0,0,0,inf,0\n",
            "line 2, column 4 (`tau3`): inf is not finite",
        ),
        (
            "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n0,0,0,0,0\n",
            "line 3, column 1 (`t`): time 0 s is not after the previous row's 0 s",
        ),
        (
            "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n1,\u{0}0,0,0,0\n",
            "line 3, column 2 (`tau1`)",
        ),
        (
            "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n1,\u{e9}0,0,0,0\n",
            "line 3, column 2 (`tau1`): `\u{e9}0` is not a number",
        ),
    ];
    for (text, needle) in cases {
        let err = read(text).unwrap_err().to_string();
        assert!(err.starts_with(needle), "{text:?}: {err}");
    }
    let err = TorqueHistory::<4>::from_csv_reader(&b"t,tau1,tau2,tau3,tau4\n0,\xFF,0,0,0\n"[..])
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 2: not UTF-8 text (byte 3 of the line is 0xFF); save the file as UTF-8"
    );
}
