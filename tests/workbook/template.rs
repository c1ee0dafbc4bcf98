//! The test that docs/tests.md offers as a template for a student's own, as it is there.

#[path = "../../docs/test_template.rs"]
mod test_template;

#[test]
fn the_template_is_the_one_docs_tests_md_shows() {
    let page = std::fs::read_to_string(crate::common::root().join("docs/tests.md")).unwrap();
    assert!(page.contains(include_str!("../../docs/test_template.rs")), "docs/tests.md shows docs/test_template.rs");
}
