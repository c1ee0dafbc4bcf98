//! Frames per second of the live viewer while its camera moves, for every example: the picture it draws
//! then (`progressive::preview_settings` of the example's defaults: 320 x 240, one sample per pixel),
//! rendered from a camera that turns and moves a little every frame, as a held key moves it. The scene
//! (and its photon map) is built once, as the window builds it once; the frames are the render only.
//!
//! Wall-clock and CPU time (from `/proc/self/stat`) are both reported: the machine may be shared, and CPU
//! time divided by the threads is what the frame would take on idle cores with perfect scaling.
//!
//! ```sh
//! cargo bench --bench viewer_fps             # 60 frames per example on 2 threads
//! cargo bench --bench viewer_fps -- 120 1    # 120 frames on 1 thread
//! ```

mod common;
#[macro_use]
#[path = "../tests/workbook/common/examples.rs"]
mod examples;

use common::cpu_time;

use lecture6::app::cli::{Cli, Example};
use lecture6::instruments::progressive::{preview_settings, quick_frame};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::render::thread_pool;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

/// The camera of frame `i`: turned by a quarter of a degree and moved by a thousandth of its distance from
/// the origin per frame, the steps a held key makes at 60 frames a second.
fn camera_at(start: &Camera, i: u32) -> Camera {
    let step = start.position.length().max(1.0) * 1e-3;
    let forward = lecture6::lesson::camera::rotation(start.yaw, start.pitch, start.roll) * lecture6::Vector::Z;
    Camera { position: start.position + forward * (step * i as f32), yaw: start.yaw + 0.25 * i as f32, ..*start }
}

fn measure<E: Example>(name: &str, frames: u32, threads: usize) {
    let cli: Cli<E> = Cli::parse_args(name, ["--quiet", "--threads", &threads.to_string()]).expect("valid arguments");
    let (base, full) = cli.prepare().expect("the example builds");
    let settings = preview_settings(&full);
    let pool = thread_pool(Some(threads)).expect("a thread pool");
    let cancel = AtomicBool::new(false);
    let (start, cpu_start) = (Instant::now(), cpu_time());
    let mut rays = 0;
    for i in 0..frames {
        let mut scene = base.clone();
        scene.camera = camera_at(&base.camera, i);
        let (_, counters) =
            pool.install(|| quick_frame(&scene, &settings, &cancel)).expect("renders").expect("not cancelled");
        rays += counters.total();
    }
    let wall = start.elapsed().as_secs_f64();
    let cpu = cpu_start.zip(cpu_time()).map(|(a, b)| (b - a).as_secs_f64());
    let cpu_fps =
        cpu.map(|c| format!("{:6.1} fps per CPU-time/{threads}", frames as f64 * threads as f64 / c.max(1e-9)));
    println!(
        "{name:16} {}x{} 1 spp: {:6.1} fps ({:6.2} ms/frame wall, {:5.2} Mrays/s), {}",
        settings.width,
        settings.height,
        frames as f64 / wall,
        wall * 1e3 / frames as f64,
        rays as f64 * 1e-6 / wall,
        cpu_fps.unwrap_or_default()
    );
}

macro_rules! measure_all {
    ($($name:ident),*) => {
        fn measure_all(frames: u32, threads: usize) {
            $(measure::<examples::$name::Options>(stringify!($name), frames, threads);)*
        }
    };
}
every_example!(measure_all);

fn main() {
    let numbers: Vec<u64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let frames = numbers.first().copied().unwrap_or(60) as u32;
    let threads = numbers.get(1).copied().unwrap_or(2) as usize;
    println!("viewer frames per second while the camera moves: {frames} frames per example, {threads} threads");
    measure_all(frames, threads);
}
