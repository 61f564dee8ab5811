//! Tests of `armdyn::trajectory::force_csv`: the force reference CSV reader refuses a bad file
//! naming the line.

use armdyn::trajectory::force_csv::*;

#[test]
fn refuses_with_the_line() {
    let e = |s: &str| {
        SampledForce::from_csv_reader(s.as_bytes())
            .unwrap_err()
            .to_string()
    };
    assert!(e("t,x\n").contains("header"));
    assert!(e("\n\r\nt,x\n").starts_with("line 3: the header must be `t,f`"));
    assert!(e("t,f\r0,1\r1,x\r").starts_with("line 3, column 2"));
    let bad = SampledForce::from_csv_reader(&b"t,f\n0,1\n1,\xFF\n"[..]).unwrap_err();
    assert_eq!(
        bad.to_string(),
        "line 3: not UTF-8 text (byte 3 of the line is 0xFF); save the file as UTF-8"
    );
    assert!(e("t,f\n0,1\n\n1,x\n").starts_with("line 4, column 2"));
    assert!(e("t,f\n0,1\n0,2\n").starts_with("line 3"));
    assert!(e("t,f\n0,-1\n1,2\n").contains("negative"));
    assert!(e("t,f\n0,1,2\n").starts_with("line 2: 3 columns, expected 2"));
    assert!(e("t,f\n0,1\n").contains("at least 2"));
    assert!(e("\n").starts_with("line 2: the input ends before the header"));
}
