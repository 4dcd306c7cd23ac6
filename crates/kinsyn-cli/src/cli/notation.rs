//! `kinsyn notation`: what a chain string means — its joints, primitive joints, parallel
//! groups and actuation — or why it is not a chain.

use super::{CliError, json, list_or_none};
use kinsyn::notation::Chain;
use std::fmt::Write as _;

pub(super) fn notation(text: &str, as_json: bool) -> Result<String, CliError> {
    let chain: Chain = text
        .parse()
        .map_err(|e| CliError::Input(format!("{text:?}: {e}")))?;
    let primitives: Vec<String> = chain
        .primitives()
        .enumerate()
        .map(|(i, (p, m))| {
            let mut s = format!("{}{}", i + 1, p.letter());
            if let Some(g) = m.group {
                s.push((b'a' + g) as char);
            }
            if m.actuated {
                s.push('!');
            }
            s
        })
        .collect();
    let actuated: Vec<usize> = chain
        .primitives()
        .enumerate()
        .filter(|(_, (_, m))| m.actuated)
        .map(|(i, _)| i + 1)
        .collect();
    if as_json {
        return Ok(json(&serde_json::json!({
            "notation": chain.to_string(),
            "letters": chain.letters(),
            "word": chain.primitive_word(),
            "parallel_groups": chain.parallel_groups(),
            "actuated": actuated,
        })));
    }
    let mut s = String::new();
    let _ = writeln!(s, "notation  {chain}");
    let _ = writeln!(s, "letters   {}", chain.letters());
    let _ = writeln!(
        s,
        "word      {} ({})",
        chain.primitive_word(),
        primitives.join(" ")
    );
    #[expect(
        clippy::cast_possible_truncation,
        reason = "one entry per group number, a u8: at most 256"
    )]
    let groups: Vec<String> = chain
        .parallel_groups()
        .iter()
        .enumerate()
        .map(|(g, m)| format!("{}: {:?}", (b'a' + g as u8) as char, m))
        .collect();
    let _ = writeln!(s, "parallel  {}", list_or_none(&groups));
    let _ = writeln!(
        s,
        "actuated  {}",
        if actuated.is_empty() {
            "none".to_string()
        } else {
            format!("{actuated:?}")
        }
    );
    Ok(s)
}
