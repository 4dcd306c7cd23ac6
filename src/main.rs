fn main() {
    let c = kinsyn::catalogue::Catalogue::generate(&kinsyn::synthesis::Options::default());
    print!("{}", c.counts_markdown());
    print!("{}", c.readme().split("## Differences").nth(1).unwrap());
    std::fs::write("/tmp/diffs.md", c.differences_markdown()).unwrap();
}
