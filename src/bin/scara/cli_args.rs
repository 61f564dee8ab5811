//! Argument types shared by the subcommands: robot choice and joint-value lists.

use clap::ValueEnum;

/// The robots built into the binary (one per `robots/*.toml`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RobotChoice {
    /// The thesis's 4-DOF SCARA (RRPR).
    Scara,
    /// The PUMA 560 (6R).
    Puma560,
    /// A planar 2R arm in a vertical plane.
    Planar2,
    /// The thesis's SCARA described in modified DH (same robot, other link frames).
    #[value(name = "scara_mdh", alias = "scara-mdh")]
    ScaraMdh,
}

/// A comma-separated list of finite numbers, as given on the command line (`0.1,-0.2,0`).
/// The length is checked later, once the robot is known.
#[derive(Debug, Clone, PartialEq)]
pub struct NumberList {
    /// The values, in order.
    pub values: Vec<f64>,
    /// The text as given, for error messages.
    pub text: String,
}

/// clap value parser for [`NumberList`]: every element must parse as a finite `f64`.
pub fn parse_number_list(text: &str) -> Result<NumberList, String> {
    if text.trim().is_empty() {
        return Err("expected a comma-separated list of numbers, got an empty value".into());
    }
    let values = text
        .split(',')
        .enumerate()
        .map(|(i, item)| {
            let item = item.trim();
            let value: f64 = item
                .parse()
                .map_err(|_| format!("element {} ('{item}') is not a number", i + 1))?;
            if value.is_finite() {
                Ok(value)
            } else {
                Err(format!(
                    "element {} ('{item}') is not finite; joint values must be finite numbers",
                    i + 1
                ))
            }
        })
        .collect::<Result<Vec<f64>, String>>()?;
    Ok(NumberList {
        values,
        text: text.to_owned(),
    })
}

/// The values of an optional list as an `N`-array (zeros when absent), or an error naming
/// the argument, the robot and the count.
pub fn joint_values<const N: usize>(
    arg: &str,
    robot: &str,
    list: Option<&NumberList>,
) -> anyhow::Result<[f64; N]> {
    let Some(list) = list else {
        return Ok([0.0; N]);
    };
    <[f64; N]>::try_from(list.values.as_slice()).map_err(|_| {
        anyhow::anyhow!(
            "{arg} '{}' has {} value(s), but robot {robot} has {N} joints",
            list.text,
            list.values.len()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_rejects() {
        assert_eq!(
            parse_number_list("0.1, -2,3e-1").unwrap().values,
            vec![0.1, -2.0, 0.3]
        );
        assert!(parse_number_list("1,abc").unwrap_err().contains("'abc'"));
        assert!(parse_number_list("1,NaN")
            .unwrap_err()
            .contains("not finite"));
        assert!(parse_number_list("inf").unwrap_err().contains("not finite"));
        assert!(parse_number_list("1,,2").is_err());
        assert!(parse_number_list("").is_err());
    }

    #[test]
    fn counts_are_checked() {
        let list = parse_number_list("1,2,3").unwrap();
        assert_eq!(
            joint_values::<3>("--q", "x", Some(&list)).unwrap(),
            [1.0, 2.0, 3.0]
        );
        let err = joint_values::<4>("--q", "scara", Some(&list)).unwrap_err();
        assert!(err.to_string().contains("--q '1,2,3' has 3 value(s)"));
        assert_eq!(joint_values::<2>("--qd", "x", None).unwrap(), [0.0; 2]);
    }
}
