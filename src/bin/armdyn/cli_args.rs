//! Argument types shared by the subcommands: robot choice, on/off switches and joint-value
//! lists.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use clap::ValueEnum;

/// On or off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OnOff {
    /// On.
    On,
    /// Off.
    Off,
}

/// clap value parser for `--robot`: the name of a generated robot (`armdyn::model::ROBOTS`, the
/// generator's registry), `-` accepted for `_` (the value is the registry's spelling).
/// `--help` and the error for an unknown name list them all.
pub fn robot_parser() -> impl TypedValueParser<Value = String> {
    PossibleValuesParser::new(armdyn::model::ROBOTS.iter().map(|name| {
        let value = PossibleValue::new(*name);
        if name.contains('_') {
            // Leaked once per robot at start-up: clap keeps aliases as `'static` strings.
            value.alias(&*Box::leak(name.replace('_', "-").into_boxed_str()))
        } else {
            value
        }
    }))
    .map(|name| name.replace('-', "_"))
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

/// The values of an optional list as the `dof` joints of `robot` (zeros when absent), or an
/// error naming the argument, the robot and the count.
pub fn joint_list(
    arg: &str,
    robot: &str,
    dof: usize,
    list: Option<&NumberList>,
) -> anyhow::Result<Vec<f64>> {
    let Some(list) = list else {
        return Ok(vec![0.0; dof]);
    };
    if list.values.len() != dof {
        anyhow::bail!(
            "{arg} '{}' has {} value(s), but robot {robot} has {dof} joints",
            list.text,
            list.values.len()
        );
    }
    Ok(list.values.clone())
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
        let err = joint_list("--q", "scara", 4, Some(&list)).unwrap_err();
        assert!(err.to_string().contains("--q '1,2,3' has 3 value(s)"));
        assert_eq!(
            joint_list("--q", "x", 3, Some(&list)).unwrap(),
            vec![1.0, 2.0, 3.0]
        );
        assert_eq!(joint_values::<2>("--qd", "x", None).unwrap(), [0.0; 2]);
    }
}
