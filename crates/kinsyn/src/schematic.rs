//! Kinematic schematics: a serial chain drawn as an SVG picture, base (ground) on the left, end
//! link on the right, one symbol per joint letter.
//!
//! The picture is a diagram, not the geometry: the joints sit on one line and the links are the
//! segments between them. Axis directions are those of the chain's reference configuration,
//! seen along y, x to the right and z up:
//!
//! - **P** (prismatic): a box on its guide, the guide along the axis (horizontal for x,
//!   vertical for z); a guide along y (the view) is a square with a dot.
//! - **R** (revolute): an axis along y (the view) is a hinge circle; an axis across it is a
//!   pin seen from the side, two bars across the axis with the axis drawn through them.
//! - **C** (cylindrical): its P and R on one axis, on a shaded band.
//! - **U** (universal): its two R on a shaded band.
//! - **S** (spherical): a ball in its socket, over its three primitive joints.
//!
//! Under each primitive joint is its position in the P/R word (the numbers of lock sets) and its
//! axis. A parallel group colours its revolutes and their labels (`a` red, `b` blue, `c` green,
//! the letter added to the label); an actuated primitive joint (`!`) is hatched and its label
//! ends in `!`. See docs/catalogue-site.md.

use crate::markup::escape;
use crate::notation::{Axis, Chain, JointKind, Mark, Primitive};
use crate::synthesis;
use std::fmt::Write as _;

/// Why a chain cannot be drawn.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SchematicError {
    /// The word or the axes given are not one per primitive joint of the chain.
    #[error(
        "a word of {word} and {axes} axis directions for a chain of {primitives} primitive joints"
    )]
    AxisCount {
        /// Length of the word given.
        word: usize,
        /// Number of axes given.
        axes: usize,
        /// Primitive joints of the chain.
        primitives: usize,
    },
    /// The P/R word does not spell the chain's letters (or the notation does not read).
    #[error("{0:?} does not spell the chain")]
    Word(String),
}

/// Horizontal room of one primitive joint.
const SLOT: f64 = 54.0;
/// Left edge of the first slot (after the ground).
const FIRST: f64 = 62.0;
/// The ground line's abscissa.
const GROUND: f64 = 30.0;
/// Height of the link line.
const LINE_Y: f64 = 70.0;
/// Height of the picture.
const HEIGHT: f64 = 150.0;
/// Ink of unmarked joints and links.
const INK: &str = "#222";

/// The colour of a parallel group (0 = `a`).
#[must_use]
pub fn group_colour(group: u8) -> &'static str {
    match group {
        0 => "#d62728",
        1 => "#1f77b4",
        2 => "#2ca02c",
        _ => "#9467bd",
    }
}

/// The letter of a parallel group (0 = `a`), as the notation writes it.
fn group_letter(group: u8) -> char {
    char::from(b'a' + group)
}

/// The SVG picture of `chain` read from the P/R `word` (a C may be read as PR or RP: the order
/// of its primitives in the word, which lock sets count), with `axes` the direction of each
/// primitive joint at the reference configuration (an entry's `word` and `axes`). The result is
/// a standalone well-formed XML element `<svg>` that can be inlined in HTML; `title` is its
/// accessible name (escaped here by [`crate::markup::escape`]; every other text is a joint
/// letter, a number or an axis letter).
///
/// Each joint letter is one `<g class="joint" data-letter="…">` element, each primitive joint
/// one `<g class="primitive">` inside it with `data-position` (in the word), `data-axis`, and
/// `data-group` / `data-actuated` when marked.
///
/// # Errors
/// If `word` and `axes` do not have one entry per primitive joint, or the word does not spell
/// the chain's letters.
pub fn svg(
    chain: &Chain,
    word: &[Primitive],
    axes: &[Axis],
    title: &str,
) -> Result<String, SchematicError> {
    let slots = slots(chain, word, axes)?;
    let n = word.len();
    let end = FIRST + slots_width(n) + 24.0;
    let width = end + 36.0;
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" class="schematic" width="{width}" height="{HEIGHT}" viewBox="0 0 {width} {HEIGHT}" role="img" aria-labelledby="schematic-title"><title id="schematic-title">{}</title>"#,
        escape(title)
    );
    s.push_str(concat!(
        r##"<defs><pattern id="ks-hatch" width="4" height="4" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">"##,
        r##"<rect width="4" height="4" fill="#fff"/><line x1="0" y1="0" x2="0" y2="4" stroke="#222" stroke-width="2.2"/></pattern></defs>"##
    ));
    s.push_str(
        r#"<g font-family="sans-serif" font-size="11" text-anchor="middle" stroke-linecap="round">"#,
    );
    ground(&mut s);
    // The links: one line from the ground to the end link, under the symbols.
    let _ = write!(
        s,
        r#"<line class="link" x1="{GROUND}" y1="{LINE_Y}" x2="{end}" y2="{LINE_Y}" stroke="{INK}" stroke-width="2.5"/>"#
    );
    for (kind, joint_slots) in &slots {
        draw_joint(&mut s, *kind, joint_slots);
    }
    end_link(&mut s, end);
    s.push_str("</g></svg>");
    Ok(s)
}

/// The picture of a catalogue entry ([`svg`] with its notation, word and axes; its id and
/// notation as the title).
///
/// # Errors
/// If the entry's notation, word and axes disagree (a corrupted entry).
pub fn entry(e: &crate::catalogue::Entry) -> Result<String, SchematicError> {
    let chain: Chain = e
        .notation
        .parse()
        .map_err(|_| SchematicError::Word(e.notation.clone()))?;
    let word =
        synthesis::parse_word(&e.word).ok_or_else(|| SchematicError::Word(e.word.clone()))?;
    let axes: Vec<Axis> = e.axes.axes().collect();
    svg(&chain, &word, &axes, &format!("{} {}", e.id, e.notation))
}

/// A primitive joint as drawn: its 1-based position in the word, kind, mark and axis.
type Slot = (usize, Primitive, Mark, Axis);

/// The joints with their primitive joints in word order, each with the mark the chain gives it
/// (a C's group or actuation mark goes to the primitive of the same kind, wherever the word puts
/// it).
fn slots(
    chain: &Chain,
    word: &[Primitive],
    axes: &[Axis],
) -> Result<Vec<(JointKind, Vec<Slot>)>, SchematicError> {
    let primitives = chain.primitives().count();
    if word.len() != primitives || axes.len() != primitives {
        return Err(SchematicError::AxisCount {
            word: word.len(),
            axes: axes.len(),
            primitives,
        });
    }
    let mut out = Vec::new();
    let mut position = 0;
    for joint in chain.joints() {
        let own = joint.kind.primitives();
        let mut marks: Vec<(Primitive, Mark)> = own
            .iter()
            .copied()
            .zip(joint.marks.iter().copied())
            .collect();
        let mut slots = Vec::new();
        for i in position..position + own.len() {
            let k = marks
                .iter()
                .position(|(p, _)| *p == word[i])
                .ok_or_else(|| SchematicError::Word(word.iter().map(|p| p.letter()).collect()))?;
            let (p, m) = marks.remove(k);
            slots.push((i + 1, p, m, axes[i]));
        }
        out.push((joint.kind, slots));
        position += own.len();
    }
    Ok(out)
}

/// Width of `n` slots.
#[allow(
    clippy::cast_precision_loss,
    reason = "a chain has at most six primitive joints"
)]
fn slots_width(n: usize) -> f64 {
    n as f64 * SLOT
}

/// The centre of the slot of 1-based position `p`.
fn centre(p: usize) -> f64 {
    FIRST + slots_width(p - 1) + SLOT / 2.0
}

/// A vertical ground line hatched on its left.
fn ground(s: &mut String) {
    let _ = write!(
        s,
        r#"<g class="ground"><line x1="{GROUND}" y1="{}" x2="{GROUND}" y2="{}" stroke="{INK}" stroke-width="2.5"/>"#,
        LINE_Y - 24.0,
        LINE_Y + 24.0
    );
    for k in 0..6 {
        let y = LINE_Y - 20.0 + f64::from(k) * 8.0;
        let _ = write!(
            s,
            r#"<line x1="{GROUND}" y1="{y}" x2="{}" y2="{}" stroke="{INK}" stroke-width="1.2"/>"#,
            GROUND - 8.0,
            y + 8.0
        );
    }
    let _ = write!(
        s,
        r##"<text x="{GROUND}" y="{}" fill="#555">base</text></g>"##,
        LINE_Y + 40.0
    );
}

/// The end link: a thick bar across the line.
fn end_link(s: &mut String, x: f64) {
    let _ = write!(
        s,
        r##"<g class="end"><line x1="{x}" y1="{}" x2="{x}" y2="{}" stroke="{INK}" stroke-width="5"/><text x="{x}" y="{}" fill="#555">end</text></g>"##,
        LINE_Y - 16.0,
        LINE_Y + 16.0,
        LINE_Y + 40.0
    );
}

/// One joint letter: its band (several primitives), its symbols, its letter above and the
/// labels of its primitive joints below.
fn draw_joint(s: &mut String, kind: JointKind, slots: &[Slot]) {
    let letter = kind.letter();
    let _ = write!(s, r#"<g class="joint" data-letter="{letter}">"#);
    let first = slots[0].0;
    let last = slots[slots.len() - 1].0;
    let (left, right) = (
        centre(first) - SLOT / 2.0 + 3.0,
        centre(last) + SLOT / 2.0 - 3.0,
    );
    if slots.len() > 1 {
        let _ = write!(
            s,
            r##"<rect class="band" x="{left}" y="{}" width="{}" height="56" rx="8" fill="#eef0f4" stroke="#b8bfcc"/>"##,
            LINE_Y - 28.0,
            right - left
        );
    }
    let _ = write!(
        s,
        r#"<text class="letter" x="{}" y="{}" font-size="14" font-weight="bold" fill="{INK}">{letter}</text>"#,
        f64::midpoint(left, right),
        LINE_Y - 34.0
    );
    if kind == JointKind::S {
        ball(s, f64::midpoint(centre(first), centre(last)));
    }
    for &(position, primitive, mark, axis) in slots {
        let colour = mark.group.map_or(INK, group_colour);
        let _ = write!(
            s,
            r#"<g class="primitive" data-position="{position}" data-axis="{axis}""#
        );
        if let Some(g) = mark.group {
            let _ = write!(s, r#" data-group="{}""#, group_letter(g));
        }
        if mark.actuated {
            s.push_str(r#" data-actuated="true""#);
        }
        s.push('>');
        let x = centre(position);
        let fill = if mark.actuated {
            "url(#ks-hatch)"
        } else {
            "#fff"
        };
        match (kind, primitive) {
            (JointKind::S, _) => sphere_slot(s, x, colour, fill),
            (_, Primitive::P) => prismatic(s, x, axis, colour, fill),
            (_, Primitive::R) => revolute(s, x, axis, colour, fill),
        }
        let label = format!(
            "{position} {axis}{}{}",
            mark.group
                .map_or(String::new(), |g| format!(" {}", group_letter(g))),
            if mark.actuated { "!" } else { "" }
        );
        let _ = write!(
            s,
            r#"<text class="label" x="{x}" y="{}" fill="{colour}"{}>{label}</text>"#,
            LINE_Y + 44.0,
            if mark.group.is_some() {
                r#" font-weight="bold""#
            } else {
                ""
            }
        );
        s.push_str("</g>");
    }
    s.push_str("</g>");
}

/// A prismatic joint: a box on its guide.
fn prismatic(s: &mut String, x: f64, axis: Axis, colour: &str, fill: &str) {
    let y = LINE_Y;
    match axis {
        Axis::X => {
            let _ = write!(
                s,
                r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="1.5"/><rect class="body" x="{}" y="{}" width="28" height="14" fill="{fill}" stroke="{colour}" stroke-width="2"/>"#,
                x - 22.0,
                y + 9.0,
                x + 22.0,
                y + 9.0,
                x - 14.0,
                y - 7.0
            );
        }
        Axis::Z => {
            let _ = write!(
                s,
                r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="1.5"/><rect class="body" x="{}" y="{}" width="14" height="28" fill="{fill}" stroke="{colour}" stroke-width="2"/>"#,
                x + 9.0,
                y - 22.0,
                x + 9.0,
                y + 22.0,
                x - 7.0,
                y - 14.0
            );
        }
        Axis::Y => {
            let _ = write!(
                s,
                r#"<rect class="body" x="{}" y="{}" width="20" height="20" fill="{fill}" stroke="{colour}" stroke-width="2"/><circle cx="{x}" cy="{y}" r="2.5" fill="{colour}"/>"#,
                x - 10.0,
                y - 10.0
            );
        }
    }
}

/// A revolute joint: a hinge circle (axis along the view) or a pin seen from the side.
fn revolute(s: &mut String, x: f64, axis: Axis, colour: &str, fill: &str) {
    let y = LINE_Y;
    match axis {
        Axis::Y => {
            let _ = write!(
                s,
                r#"<circle class="body" cx="{x}" cy="{y}" r="9" fill="{fill}" stroke="{colour}" stroke-width="2.5"/>"#
            );
        }
        Axis::X => {
            // The pin along the line: bars across it at both ends.
            let _ = write!(
                s,
                r#"<line x1="{}" y1="{y}" x2="{}" y2="{y}" stroke="{colour}" stroke-width="1" stroke-dasharray="4 2"/><rect class="body" x="{}" y="{}" width="12" height="12" fill="{fill}" stroke="none"/><line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="3"/><line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="3"/>"#,
                x - 20.0,
                x + 20.0,
                x - 6.0,
                y - 6.0,
                x - 6.0,
                y - 11.0,
                x - 6.0,
                y + 11.0,
                x + 6.0,
                y - 11.0,
                x + 6.0,
                y + 11.0
            );
        }
        Axis::Z => {
            let _ = write!(
                s,
                r#"<line x1="{x}" y1="{}" x2="{x}" y2="{}" stroke="{colour}" stroke-width="1" stroke-dasharray="4 2"/><rect class="body" x="{}" y="{}" width="12" height="12" fill="{fill}" stroke="none"/><line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="3"/><line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="3"/>"#,
                y - 20.0,
                y + 20.0,
                x - 6.0,
                y - 6.0,
                x - 11.0,
                y - 6.0,
                x + 11.0,
                y - 6.0,
                x - 11.0,
                y + 6.0,
                x + 11.0,
                y + 6.0
            );
        }
    }
}

/// The ball and socket of a spherical joint, centred at `x`.
fn ball(s: &mut String, x: f64) {
    let y = LINE_Y;
    let _ = write!(
        s,
        r##"<path d="M {} {} A 17 17 0 0 0 {} {}" fill="none" stroke="{INK}" stroke-width="2.5"/><circle class="ball" cx="{x}" cy="{y}" r="12" fill="#fff" stroke="{INK}" stroke-width="2.5"/>"##,
        x - 12.0,
        y - 12.0,
        x - 12.0,
        y + 12.0
    );
}

/// A primitive joint of a spherical joint: a dot on the ball's line (hatched when actuated).
fn sphere_slot(s: &mut String, x: f64, colour: &str, fill: &str) {
    let _ = write!(
        s,
        r#"<circle class="body" cx="{x}" cy="{}" r="4" fill="{fill}" stroke="{colour}" stroke-width="1.5"/>"#,
        LINE_Y + 24.0
    );
}
