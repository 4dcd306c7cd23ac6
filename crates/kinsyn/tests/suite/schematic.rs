//! The joint schematics (src/schematic.rs): every committed catalogue entry drawn with its
//! letters, axes and parallel groups, actuated joints marked, and the axes checked against the
//! primitives.

use kinsyn::catalogue::Catalogue;
use kinsyn::notation::{Axis, Chain, Primitive};
use kinsyn::schematic::{SchematicError, entry, group_colour, svg};
use kinsyn::synthesis;

/// The values of attribute `name` in document order.
fn attributes<'a>(svg: &'a str, name: &str) -> Vec<&'a str> {
    let key = format!(" {name}=\"");
    svg.match_indices(&key)
        .map(|(i, _)| {
            let rest = &svg[i + key.len()..];
            &rest[..rest.find('"').unwrap()]
        })
        .collect()
}

fn word(chain: &Chain) -> Vec<Primitive> {
    synthesis::parse_word(&chain.primitive_word()).unwrap()
}

fn axes(word: &str) -> Vec<Axis> {
    word.chars()
        .map(|c| Axis::from_letter(c).unwrap())
        .collect()
}

#[test]
fn every_catalogue_entry_draws_one_symbol_per_letter_with_its_groups() {
    let cat = Catalogue::committed().unwrap();
    assert_eq!(cat.entries.len(), 485);
    for e in &cat.entries {
        let svg = entry(e).unwrap();
        assert!(
            svg.starts_with("<svg ") && svg.ends_with("</svg>"),
            "{}",
            e.id
        );
        // One joint symbol per letter of the entry, in order.
        let letters: String = attributes(&svg, "data-letter").concat();
        assert_eq!(letters, e.letters, "{}", e.id);
        // One primitive per character of the word, numbered 1.., with the word's axes.
        let positions: Vec<usize> = attributes(&svg, "data-position")
            .iter()
            .map(|p| p.parse().unwrap())
            .collect();
        assert_eq!(
            positions,
            (1..=e.word.len()).collect::<Vec<_>>(),
            "{}",
            e.id
        );
        assert_eq!(attributes(&svg, "data-axis").concat(), e.axes.as_str());
        // The parallel groups as the catalogue file records them.
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for (i, p) in svg.match_indices("data-position=\"") {
            let tail = &svg[i..svg[i..].find('>').unwrap() + i];
            if let Some(g) = attributes(tail, "data-group").first() {
                let g = usize::from(g.as_bytes()[0] - b'a');
                groups.resize(groups.len().max(g + 1), Vec::new());
                let pos = &svg[i + p.len()..];
                groups[g].push(pos[..pos.find('"').unwrap()].parse().unwrap());
            }
        }
        assert_eq!(groups, e.parallel_groups, "{}", e.id);
        // Tags balance (the browser test parses the pages as XML too).
        assert_eq!(
            svg.matches("<g").count(),
            svg.matches("</g>").count(),
            "{}",
            e.id
        );
    }
}

#[test]
fn actuated_joints_are_hatched_and_marked() {
    // The 3-UPS leg of paper 000 §5: the first R of the U and the P actuated.
    let chain: Chain = "U(!,-)P!S".parse().unwrap();
    let svg = svg(&chain, &word(&chain), &axes("xyzxyz"), "U(!,-)P!S").unwrap();
    assert_eq!(attributes(&svg, "data-letter"), ["U", "P", "S"]);
    assert_eq!(svg.matches(r#"data-actuated="true""#).count(), 2);
    assert_eq!(svg.matches("url(#ks-hatch)").count(), 2);
    assert!(svg.contains(">1 x!</text>") && svg.contains(">3 z!</text>"));
    // One ball for the S.
    assert_eq!(svg.matches(r#"class="ball""#).count(), 1);
}

#[test]
fn revolutes_along_the_view_are_circles_and_across_it_bars() {
    // RRR about y, x, z: one hinge circle (y), two pins seen from the side.
    let chain: Chain = "RRR".parse().unwrap();
    let picture = svg(&chain, &word(&chain), &axes("yxz"), "RRR").unwrap();
    assert_eq!(picture.matches("<circle").count(), 1);
    assert_eq!(picture.matches(r#"stroke-width="3""#).count(), 4);
    // The paper's three groups: each coloured with its group's colour.
    let chain: Chain = "RaU(a,b)U(b,c)Rc".parse().unwrap();
    let svg = svg(&chain, &word(&chain), &axes("zzxxyy"), "<&>").unwrap();
    assert!(svg.contains("<title id=\"schematic-title\">&lt;&amp;&gt;</title>"));
    assert_eq!(attributes(&svg, "data-group").concat(), "aabbcc");
    for g in 0..3 {
        assert!(svg.contains(group_colour(g)));
    }
}

#[test]
fn axes_must_match_the_primitives() {
    let chain: Chain = "PPCU".parse().unwrap();
    assert_eq!(
        svg(&chain, &word(&chain), &axes("xyz"), "").unwrap_err(),
        SchematicError::AxisCount {
            word: 6,
            axes: 3,
            primitives: 6
        }
    );
}
