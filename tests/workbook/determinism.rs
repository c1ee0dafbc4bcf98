//! The same command gives the same picture, byte for byte, whatever the thread count: every example at a
//! small size with 1, 2 and 8 threads (more threads than the test machine has cores, so rows are stolen
//! between workers in an order that changes from run to run).

use crate::common;

use common::examples::bitmap_textures;

macro_rules! thread_count_independent {
    ($($name:ident),* $(,)?) => {$(
        #[test]
        fn $name() {
            type Args = common::examples::$name::Options;
            let size = ["--width", "96", "--height", "72", "--spp", "2"];
            let frame = |threads: &str| {
                let args: Vec<&str> = size.iter().copied().chain(["--threads", threads]).collect();
                common::render::<Args>(&args)
            };
            // `common::render` checks that no sample came back NaN or infinite.
            let one = frame("1");
            for threads in ["2", "8"] {
                assert!(frame(threads) == one, "{}: the picture changed with {threads} threads", stringify!($name));
            }
        }
    )*};
}

every_example!(thread_count_independent);

#[test]
fn different_seeds_give_different_anti_aliasing() {
    let a = common::render::<bitmap_textures::Options>(&["--seed", "1", "--width", "160", "--height", "120"]);
    let b = common::render::<bitmap_textures::Options>(&["--seed", "2", "--width", "160", "--height", "120"]);
    // The seed reaches the sampler: the pixels differ, and only as two samplings of one picture do, so the
    // picture's mean brightness agrees to a percent.
    let d = lecture6::instruments::compare::difference(&a.to_rgb8(), &b.to_rgb8()).unwrap();
    let mean = |f: &lecture6::lesson::frame::Frame| {
        f.pixels.iter().map(|p| (p.r() + p.g() + p.b()) as f64).sum::<f64>() / f.pixels.len() as f64
    };
    let (mean_a, mean_b) = (mean(&a), mean(&b));
    assert!(d.max_diff > 0, "seeds 1 and 2 gave the same picture");
    assert!((mean_a / mean_b - 1.0).abs() < 0.01, "mean brightness {mean_a} against {mean_b}");
}

#[test]
fn glossy_is_identical_for_one_and_two_threads_with_every_sampler() {
    use common::examples::glossy;
    for sampler in ["random", "stratified", "joint"] {
        let args = |threads| ["--threads", threads, "--width", "96", "--height", "72", "--sampler", sampler];
        let one = common::render::<glossy::Options>(&args("1"));
        let two = common::render::<glossy::Options>(&args("2"));
        assert!(one == two, "{sampler}: the picture changed with the thread count");
    }
}
