//! Tests of `armdyn::trajectory::pose_csv`: the pose CSV reader: the exact header, errors with
//! their line and column, a byte-order mark and CRLF, text that is not UTF-8.

use armdyn::csv_text::CsvError;
use armdyn::trajectory::SampledTrajectory;

fn read(text: &str) -> Result<SampledTrajectory, CsvError> {
    SampledTrajectory::from_csv_reader(text.as_bytes())
}

#[test]
fn header_must_be_exact() {
    let err = read("time,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
    assert!(matches!(err, CsvError::Header { line: 1, .. }), "{err}");
    let err = read("t,x,y,z\n0,0,0,0\n").unwrap_err();
    assert!(matches!(err, CsvError::Header { .. }), "{err}");
    let err = read("0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
    assert!(matches!(err, CsvError::Header { .. }), "{err}");
    assert!(matches!(read("").unwrap_err(), CsvError::NoHeader { .. }));
    // Spaces around names are fine.
    assert!(read(" t , x , y , z , yaw \n0,0,0,0,0\n1,0,0,0,0\n").is_ok());
}

#[test]
fn errors_name_line_and_column() {
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0\n").unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 3, column 4: missing column `z` (expected 5 columns `t,x,y,z,yaw`, found 3)"
    );
    let err = read("t,x,y,z,roll,pitch,yaw\n0,0,0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 3, column 6: missing column `pitch` (expected 7 columns `t,x,y,z,roll,pitch,yaw`, found 5)"
    );
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,0,9\n").unwrap_err();
    assert!(
        matches!(
            err,
            CsvError::ExtraFields {
                line: 3,
                found: 6,
                ..
            }
        ),
        "{err}"
    );
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,inf,0\n").unwrap_err();
    assert_eq!(err.to_string(), "line 3, column 4 (`z`): inf is not finite");
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,NaN\n").unwrap_err();
    assert!(
        matches!(
            err,
            CsvError::NonFinite {
                line: 3,
                column: 5,
                ..
            }
        ),
        "{err}"
    );
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n2,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
    assert!(
        matches!(err, CsvError::NotIncreasing { line: 4, .. }),
        "{err}"
    );
    let err = read("t,x,y,z,yaw\n-1,0,0,0,0\n2,0,0,0,0\n").unwrap_err();
    assert!(
        matches!(err, CsvError::NegativeStart { line: 2, .. }),
        "{err}"
    );
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n").unwrap_err();
    assert_eq!(
        err.to_string(),
        "1 data row(s) after the header; the file needs at least 2"
    );
    let err = read("t,x,y,z,yaw\n0,0,0,0,0\n\n1,0,0,0,x\n").unwrap_err();
    assert!(
        matches!(
            err,
            CsvError::NotNumeric {
                line: 4,
                column: 5,
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn byte_order_mark_and_crlf_are_accepted() {
    let plain = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.6,0.1,0.1,1\n";
    let expected = read(plain).unwrap();
    let crlf = plain.replace('\n', "\r\n");
    assert_eq!(read(&crlf).unwrap(), expected);
    assert_eq!(read(&format!("\u{feff}{plain}")).unwrap(), expected);
    assert_eq!(read(&format!("\u{feff}{crlf}")).unwrap(), expected);
    // Lines are still counted right, blank ones included.
    let err = read("\u{feff}t,x,y,z,yaw\r\n0,0,0,0,0\r\n\r\n1,0,0,0,x\r\n").unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 4, column 5 (`yaw`): `x` is not a number"
    );
    // A byte-order mark anywhere else is not ignored.
    let err = read("t,x,y,z,yaw\n\u{feff}0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
    assert!(
        matches!(
            err,
            CsvError::NotNumeric {
                line: 2,
                column: 1,
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn text_that_is_not_utf8_names_its_line() {
    let err =
        SampledTrajectory::from_csv_reader(&b"t,x,y,z,yaw\r\n0,0,0,0,0\r\n1,0,\xC3(,0,0\r\n"[..])
            .unwrap_err();
    assert_eq!(
        err.to_string(),
        "line 3: not UTF-8 text (byte 5 of the line is 0xC3); save the file as UTF-8"
    );
}
