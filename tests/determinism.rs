//! The same command gives the same picture, byte for byte, whatever the thread count.

mod common;

use lecture6::scenes::bitmap_textures;

#[test]
fn bitmap_textures_is_identical_for_one_and_two_threads() {
    let one = common::render::<bitmap_textures::Args>(&["--threads", "1", "--width", "160", "--height", "120"]);
    let two = common::render::<bitmap_textures::Args>(&["--threads", "2", "--width", "160", "--height", "120"]);
    assert!(one == two, "the picture changed with the thread count");
}

#[test]
fn different_seeds_give_different_anti_aliasing() {
    let a = common::render::<bitmap_textures::Args>(&["--seed", "1", "--width", "160", "--height", "120"]);
    let b = common::render::<bitmap_textures::Args>(&["--seed", "2", "--width", "160", "--height", "120"]);
    assert_ne!(a, b, "the seed must reach the sampler");
}

#[test]
fn model_transform_is_identical_for_one_and_two_threads() {
    use lecture6::scenes::model_transform::Args;
    let one = common::render::<Args>(&["--threads", "1", "--width", "160", "--height", "120"]);
    let two = common::render::<Args>(&["--threads", "2", "--width", "160", "--height", "120"]);
    assert!(one == two, "the picture changed with the thread count");
}

#[test]
fn glossy_is_identical_for_one_and_two_threads_with_either_sampler() {
    use lecture6::scenes::glossy;
    for sampler in ["random", "stratified"] {
        let args = |threads| ["--threads", threads, "--width", "96", "--height", "72", "--sampler", sampler];
        let one = common::render::<glossy::Args>(&args("1"));
        let two = common::render::<glossy::Args>(&args("2"));
        assert!(one == two, "{sampler}: the picture changed with the thread count");
    }
}
