//! Small text tables for the comparisons the CLI prints (Markdown or plain, aligned).

use std::fmt;

/// Horizontal alignment of a column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    /// Text to the left (the default for text columns).
    Left,
    /// Text to the right (the default for columns whose cells are all numbers).
    Right,
}

/// A table of text cells with a header row, laid out with aligned columns.
///
/// Columns whose body cells all parse as numbers (or are empty, or `-`) are right-aligned
/// unless [`Table::align`] says otherwise. Rows shorter than the widest row are padded
/// with empty cells. Widths count characters, not bytes.
///
/// # Example
///
/// ```
/// use armdyn::report::Table;
///
/// let table = Table::new(["controller", "rms error (rad)"])
///     .row(["pid", "0.0123"])
///     .row(["computed torque", "0.0001"]);
/// assert_eq!(
///     table.markdown(),
///     "| controller      | rms error (rad) |\n\
///      | :-------------- | --------------: |\n\
///      | pid             |          0.0123 |\n\
///      | computed torque |          0.0001 |\n"
/// );
/// assert_eq!(
///     table.plain(),
///     "controller       rms error (rad)\n\
///      ---------------  ---------------\n\
///      pid                       0.0123\n\
///      computed torque           0.0001\n"
/// );
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Table {
    headers: Vec<String>,
    rows: Vec<Vec<String>>,
    align: Vec<Option<Align>>,
}

impl Table {
    /// A table with these column headers and no rows.
    pub fn new<I, S>(headers: I) -> Self
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        Self {
            headers: headers.into_iter().map(Into::into).collect(),
            rows: Vec::new(),
            align: Vec::new(),
        }
    }

    /// Adds a row of cells.
    #[must_use]
    pub fn row<I, S>(mut self, cells: I) -> Self
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        self.push_row(cells);
        self
    }

    /// Adds a row of cells, in place (for loops).
    pub fn push_row<I, S>(&mut self, cells: I)
    where
        I: IntoIterator<Item = S>,
        S: Into<String>,
    {
        self.rows.push(cells.into_iter().map(Into::into).collect());
    }

    /// Sets the alignment of column `column` (0-based), overriding the automatic choice.
    #[must_use]
    pub fn align(mut self, column: usize, align: Align) -> Self {
        if self.align.len() <= column {
            self.align.resize(column + 1, None);
        }
        self.align[column] = Some(align);
        self
    }

    /// Number of body rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether the table has no body rows.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    fn columns(&self) -> usize {
        self.rows
            .iter()
            .map(Vec::len)
            .chain([self.headers.len()])
            .max()
            .unwrap_or(0)
    }

    fn cell(row: &[String], c: usize) -> &str {
        row.get(c).map_or("", String::as_str)
    }

    fn alignment(&self, c: usize) -> Align {
        if let Some(Some(a)) = self.align.get(c) {
            return *a;
        }
        let mut any = false;
        for row in &self.rows {
            let cell = Self::cell(row, c).trim();
            if cell.is_empty() || cell == "-" {
                continue;
            }
            if cell.parse::<f64>().is_err() {
                return Align::Left;
            }
            any = true;
        }
        if any {
            Align::Right
        } else {
            Align::Left
        }
    }

    /// Column widths, with cells transformed by `f` (escaping) and at least `min`.
    fn widths(&self, f: &dyn Fn(&str) -> String, min: usize) -> Vec<usize> {
        (0..self.columns())
            .map(|c| {
                self.rows
                    .iter()
                    .chain([&self.headers])
                    .map(|r| f(Self::cell(r, c)).chars().count())
                    .max()
                    .unwrap_or(0)
                    .max(min)
            })
            .collect()
    }

    fn line(
        cells: impl Iterator<Item = String>,
        widths: &[usize],
        aligns: &[Align],
        sep: &str,
        ends: (&str, &str),
    ) -> String {
        let parts: Vec<String> = cells
            .zip(widths.iter().zip(aligns))
            .map(|(text, (&w, &a))| match a {
                Align::Left => format!("{text:<w$}"),
                Align::Right => format!("{text:>w$}"),
            })
            .collect();
        let mut line = format!("{}{}{}", ends.0, parts.join(sep), ends.1);
        // Plain tables: no trailing blanks after a left-aligned last column.
        if ends.1.is_empty() {
            line.truncate(line.trim_end().len());
        }
        line.push('\n');
        line
    }

    /// GitHub-flavoured Markdown: a header row, an alignment row (`:---` / `---:`), body
    /// rows; `|` in cells escaped as `\|`.
    pub fn markdown(&self) -> String {
        let esc = |s: &str| s.replace('|', "\\|");
        let widths = self.widths(&esc, 3);
        let aligns: Vec<Align> = (0..widths.len()).map(|c| self.alignment(c)).collect();
        let row = |r: &[String]| {
            Self::line(
                (0..widths.len()).map(|c| esc(Self::cell(r, c))),
                &widths,
                &aligns,
                " | ",
                ("| ", " |"),
            )
        };
        let mut out = row(&self.headers);
        let rule: Vec<String> = widths
            .iter()
            .zip(&aligns)
            .map(|(&w, a)| match a {
                Align::Left => format!(":{}", "-".repeat(w - 1)),
                Align::Right => format!("{}:", "-".repeat(w - 1)),
            })
            .collect();
        out.push_str(&format!("| {} |\n", rule.join(" | ")));
        for r in &self.rows {
            out.push_str(&row(r));
        }
        out
    }

    /// Plain text for a terminal: columns separated by two spaces, a dashed rule under the
    /// header.
    pub fn plain(&self) -> String {
        let id = |s: &str| s.to_owned();
        let widths = self.widths(&id, 1);
        let aligns: Vec<Align> = (0..widths.len()).map(|c| self.alignment(c)).collect();
        let row = |r: &[String]| {
            Self::line(
                (0..widths.len()).map(|c| Self::cell(r, c).to_owned()),
                &widths,
                &aligns,
                "  ",
                ("", ""),
            )
        };
        let mut out = row(&self.headers);
        let rule: Vec<String> = widths.iter().map(|&w| "-".repeat(w)).collect();
        out.push_str(&rule.join("  "));
        out.push('\n');
        for r in &self.rows {
            out.push_str(&row(r));
        }
        out
    }
}

/// The plain layout.
impl fmt::Display for Table {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.plain())
    }
}
