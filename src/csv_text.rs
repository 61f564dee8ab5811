//! The text of a CSV input file, with line numbers for messages (feature `std`).
//!
//! Shared by the CSV readers ([`crate::trajectory::SampledTrajectory::from_csv_reader`],
//! [`crate::sim::torque_history::TorqueHistory::from_csv_reader`],
//! [`crate::trajectory::force_csv::SampledForce::from_csv_reader`]): the whole input is read
//! once, a leading UTF-8 byte-order mark (as spreadsheet programs write it) is dropped, the
//! text must be UTF-8, and lines may end in LF, CRLF or CR (what the `csv` crate splits
//! records on). Records are trimmed of spaces; blank lines are skipped by the caller.

use std::io::Read;

const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Why the text of a CSV file could not be read.
#[derive(Debug)]
pub(crate) enum TextError {
    /// Reading failed.
    Io(std::io::Error),
    /// A byte sequence that is not UTF-8, on `line` (from 1) at byte `offset` of the line
    /// (from 1).
    NotUtf8 { line: u64, offset: u64, byte: u8 },
}

/// The bytes of a CSV input, checked to be UTF-8, without a leading byte-order mark.
pub(crate) struct CsvText {
    bytes: Vec<u8>,
}

impl CsvText {
    /// Reads all of `reader`.
    pub(crate) fn read<R: Read>(mut reader: R) -> Result<Self, TextError> {
        let mut bytes = Vec::new();
        reader.read_to_end(&mut bytes).map_err(TextError::Io)?;
        if bytes.starts_with(BOM) {
            bytes.drain(..BOM.len());
        }
        let text = Self { bytes };
        if let Err(e) = std::str::from_utf8(&text.bytes) {
            let at = e.valid_up_to();
            let line_start = text.bytes[..at]
                .iter()
                .rposition(|&b| b == b'\n' || b == b'\r')
                .map_or(0, |p| p + 1);
            return Err(TextError::NotUtf8 {
                line: text.line_at(at as u64),
                offset: (at - line_start + 1) as u64,
                byte: text.bytes[at],
            });
        }
        Ok(text)
    }

    /// A CSV reader over the text: no header handling (the callers check it), records of any
    /// length, spaces around fields trimmed.
    pub(crate) fn reader(&self) -> csv::Reader<&[u8]> {
        csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .trim(csv::Trim::All)
            .from_reader(self.bytes.as_slice())
    }

    /// The lines of the text, without their ends (LF, CRLF or a lone CR), blank ones
    /// included, for a reader that splits fields itself.
    pub(crate) fn lines(&self) -> impl Iterator<Item = &str> + '_ {
        // Checked to be UTF-8 in `read`.
        let text = std::str::from_utf8(&self.bytes).unwrap_or_default();
        let mut rest = Some(text);
        std::iter::from_fn(move || {
            let s = rest?;
            match s.find(['\n', '\r']) {
                Some(i) => {
                    let skip = if s[i..].starts_with("\r\n") { 2 } else { 1 };
                    rest = Some(&s[i + skip..]);
                    Some(&s[..i])
                }
                None => {
                    rest = None;
                    Some(s)
                }
            }
        })
    }

    /// The line (from 1) of a record that the reader started at byte `byte`: a record's
    /// position is where the reader started on it, before the blank lines it skipped, so
    /// move past them to the record itself. LF, CRLF and a lone CR each end a line.
    pub(crate) fn line_at(&self, byte: u64) -> u64 {
        let bytes = &self.bytes;
        let mut end = usize::try_from(byte).map_or(bytes.len(), |b| b.min(bytes.len()));
        while end < bytes.len() && (bytes[end] == b'\n' || bytes[end] == b'\r') {
            end += 1;
        }
        let breaks = bytes[..end]
            .iter()
            .enumerate()
            .filter(|&(i, &b)| b == b'\n' || (b == b'\r' && bytes.get(i + 1) != Some(&b'\n')))
            .count();
        1 + breaks as u64
    }

    /// The line of a record (0 if it has no position).
    pub(crate) fn line_of(&self, record: &csv::StringRecord) -> u64 {
        record.position().map_or(0, |p| self.line_at(p.byte()))
    }

    /// The line of a reader error (0 if it has no position).
    pub(crate) fn error_line(&self, error: &csv::Error) -> u64 {
        error.position().map_or(0, |p| self.line_at(p.byte()))
    }
}

/// `true` for a record that is a blank line (nothing but spaces).
pub(crate) fn is_blank(record: &csv::StringRecord) -> bool {
    record.len() == 1 && record[0].is_empty()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &[u8]) -> Vec<u64> {
        let t = CsvText::read(text).unwrap();
        let mut reader = t.reader();
        reader.records().map(|r| t.line_of(&r.unwrap())).collect()
    }

    #[test]
    fn lines_count_lf_crlf_and_cr_and_skip_blank_lines() {
        assert_eq!(lines(b"a\nb\n\nc\n"), [1, 2, 4]);
        assert_eq!(lines(b"a\r\nb\r\n\r\nc\r\n"), [1, 2, 4]);
        assert_eq!(lines(b"a\rb\r\rc"), [1, 2, 4]);
        assert_eq!(lines(b"\xEF\xBB\xBFa\r\n\r\nb"), [1, 3]);
    }

    #[test]
    fn lines_split_like_the_reader() {
        let t = CsvText::read(&b"\xEF\xBB\xBFa\r\nb\rc\n\nd"[..]).unwrap();
        assert_eq!(t.lines().collect::<Vec<_>>(), ["a", "b", "c", "", "d"]);
        let t = CsvText::read(&b"a\n"[..]).unwrap();
        assert_eq!(t.lines().collect::<Vec<_>>(), ["a", ""]);
    }

    #[test]
    fn byte_order_mark_is_dropped() {
        let t = CsvText::read(&b"\xEF\xBB\xBFt,x\n"[..]).unwrap();
        let mut reader = t.reader();
        let header = reader.records().next().unwrap().unwrap();
        assert_eq!(&header[0], "t");
    }

    #[test]
    fn invalid_utf8_names_line_and_byte() {
        match CsvText::read(&b"t,x\r\n0,1\r\n1,\xFF\n"[..]) {
            Err(TextError::NotUtf8 { line, offset, byte }) => {
                assert_eq!((line, offset, byte), (3, 3, 0xFF));
            }
            other => panic!("expected NotUtf8, got {:?}", other.map(|_| ())),
        }
    }
}
