//! The page: its data as one JSON object, inlined with the script into `page.html`.

use std::fmt::Write as _;

use super::surface_mesh::Mesh;
use super::ViewEvent;

/// The page's template; `/*DATA*/` becomes the data, `/*SCRIPT*/` the script.
const TEMPLATE: &str = include_str!("page.html");
/// The viewer's script.
const SCRIPT: &str = include_str!("viewer.js");

/// The data of a page, written as JSON while it is collected (flat arrays of rounded
/// numbers, to keep the file small).
pub(super) struct Data {
    title: String,
    head: String,
    times: String,
    points: String,
    path: String,
    reference: String,
    force: String,
    force_ref: String,
    surfaces: String,
    events: String,
    frames: usize,
}

/// `x` with `decimals` decimals, trailing zeros dropped; `null` if not finite.
fn num(out: &mut String, x: f64, decimals: usize) {
    if !x.is_finite() {
        out.push_str("null");
        return;
    }
    let start = out.len();
    let _ = write!(out, "{x:.decimals$}");
    if out[start..].contains('.') {
        let trimmed = out[start..]
            .trim_end_matches('0')
            .trim_end_matches('.')
            .len();
        out.truncate(start + trimmed);
    }
    if &out[start..] == "-0" {
        out.truncate(start);
        out.push('0');
    }
}

/// Appends `,`-separated `xs` to a JSON array under construction.
fn push_all(out: &mut String, xs: &[f64], decimals: usize) {
    for &x in xs {
        if !out.is_empty() {
            out.push(',');
        }
        num(out, x, decimals);
    }
}

/// A JSON string.
fn string(s: &str) -> String {
    serde_json::Value::from(s).to_string()
}

/// Positions to 10 um.
const POSITION_DECIMALS: usize = 5;

impl Data {
    /// A page titled `title` of `robot` (its joints `joints`), `points` points a frame.
    pub(super) fn new(title: &str, robot: &str, joints: &[&str], points: usize) -> Self {
        let names: Vec<String> = joints.iter().map(|j| string(j)).collect();
        Self {
            title: title.to_string(),
            head: format!(
                "\"title\":{},\"robot\":{},\"joints\":[{}],\"points\":{points}",
                string(title),
                string(robot),
                names.join(",")
            ),
            times: String::new(),
            points: String::new(),
            path: String::new(),
            reference: String::new(),
            force: String::new(),
            force_ref: String::new(),
            surfaces: String::new(),
            events: String::new(),
            frames: 0,
        }
    }

    /// One frame at `t` (s): the robot's `points` (base, frame origins, tool), the tool's
    /// recorded position, the reference's, the contact force and its reference (N).
    pub(super) fn push_frame(
        &mut self,
        t: f64,
        points: &[[f64; 3]],
        tool: [f64; 3],
        reference: [f64; 3],
        force: [f64; 3],
        force_ref: [f64; 3],
    ) {
        push_all(&mut self.times, &[t], 6);
        for p in points {
            push_all(&mut self.points, p, POSITION_DECIMALS);
        }
        push_all(&mut self.path, &tool, POSITION_DECIMALS);
        push_all(&mut self.reference, &reference, POSITION_DECIMALS);
        push_all(&mut self.force, &force, 2);
        push_all(&mut self.force_ref, &force_ref, 2);
        self.frames += 1;
    }

    /// A surface.
    pub(super) fn push_surface(&mut self, m: Mesh) {
        let list = |polys: &[Vec<[f64; 3]>]| {
            let each: Vec<String> = polys
                .iter()
                .map(|poly| {
                    let mut s = String::new();
                    for p in poly {
                        push_all(&mut s, p, POSITION_DECIMALS);
                    }
                    format!("[{s}]")
                })
                .collect();
            each.join(",")
        };
        if !self.surfaces.is_empty() {
            self.surfaces.push(',');
        }
        let _ = write!(
            self.surfaces,
            "{{\"fills\":[{}],\"lines\":[{}]}}",
            list(&m.fills),
            list(&m.lines)
        );
    }

    /// An event.
    pub(super) fn push_event(&mut self, e: &ViewEvent) {
        if !self.events.is_empty() {
            self.events.push(',');
        }
        self.events.push_str("{\"t\":");
        num(&mut self.events, e.t_s, 6);
        let _ = write!(self.events, ",\"text\":{}}}", string(&e.text));
    }

    /// The object.
    fn json(&self) -> String {
        format!(
            "{{{},\"frames\":{},\"t\":[{}],\"xyz\":[{}],\"path\":[{}],\"ref\":[{}],\"force\":[{}],\"force_ref\":[{}],\"surfaces\":[{}],\"events\":[{}]}}",
            self.head,
            self.frames,
            self.times,
            self.points,
            self.path,
            self.reference,
            self.force,
            self.force_ref,
            self.surfaces,
            self.events
        )
    }
}

/// The page of `data`.
pub(super) fn html(data: &Data) -> String {
    // `</` cannot end the script early: JSON strings escape it.
    let json = data.json().replace("</", "<\\/");
    TEMPLATE
        .replace("/*DATA*/", &json)
        .replace("/*SCRIPT*/", SCRIPT)
        .replace("{{TITLE}}", &html_text(&data.title))
}

/// `s` as HTML text.
fn html_text(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_rounded_without_trailing_zeros_and_non_finite_is_null() {
        let mut s = String::new();
        push_all(&mut s, &[0.25, -1e-9, 3.0, f64::NAN, 0.123_456_7], 5);
        assert_eq!(s, "0.25,0,3,null,0.12346");
    }
}
