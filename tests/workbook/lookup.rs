//! `--view lookup` and `--view lookup-value` show what a shader actually read, where `--view uv` shows where
//! the hit says it should read: a student's shader that swaps u and v before reading its texture is seen in
//! the first and not in the second.

use lecture6::instruments::debug_view::{DebugImage, DebugView, render_view};
use lecture6::lesson::color::to_srgb8;
use lecture6::lesson::render::RenderSettings;
use lecture6::prelude::*;

/// How the student's shader reads its texture.
#[derive(Clone, Copy, PartialEq)]
enum Reading {
    /// At the hit's (u, v), through `ColorSource::at`, as the workbook's shaders do.
    AtUv,
    /// At (v, u): the student's mistake.
    AtVu,
    /// At the hit's (u, v), through `Texture::get_tex_color` called directly.
    Direct,
}

/// A student's diffuse shader with a texture, written as `docs/homework-api.md` shows.
struct Diffuse {
    texture: ColorSource,
    reading: Reading,
}

impl Shader for Diffuse {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let (u, v) = info.uv();
        let color = match (self.reading, self.texture.texture()) {
            (Reading::Direct, Some(texture)) => texture.get_tex_color(ray, info),
            (Reading::AtVu, _) => self.texture.at(ray, &info.with_tex_coords(TexCoords::new(v, u)), ctx),
            _ => self.texture.at(ray, info, ctx),
        };
        color * diffuse_light(ctx, info, faceforward(info.normal, ray.dir))
    }

    fn texture(&self) -> Option<&dyn Texture> {
        self.texture.texture()
    }
}

/// The bitmap example's scene as a homework copies it: the tiled floor and the planet under the student's
/// shader, the magnified checker sphere a mirror (which reads no texture, and sees the floor), the cube
/// plain-coloured.
fn homework(reading: Reading) -> Scene {
    let camera = Camera { position: Vector::new(0.0, 48.0, -95.0), pitch: -20.0, fov: 75.0, ..Camera::default() };
    let mut scene = Scene::new(camera);
    scene.ambient = Color::gray(0.12);
    scene.lights.push(PointLight::new(Vector::new(-60.0, 160.0, -90.0), Color::WHITE, 38000.0));
    let own = |name: &str, tile_size: f32| -> Diffuse {
        let texture = texture(name).unwrap().with_tile_size(tile_size);
        Diffuse { texture: texture.into(), reading }
    };
    scene.add(Node::new(Plane::new(0.0, 200.0), own("floor_tiles.png", 40.0)));
    scene.add(Node::new(Sphere::new(Vector::new(-42.0, 20.0, 25.0), 20.0), own("world.png", 1.0)));
    scene.add(Node::new(Sphere::new(Vector::new(0.0, 20.0, 25.0), 20.0), Reflection::new(0.9)));
    scene.add(Node::new(Cube::new(Vector::new(42.0, 16.0, 25.0), 16.0), Lambert::new(Color::gray(0.5))));
    scene
}

const WIDTH: u32 = 80;
const HEIGHT: u32 = 60;

/// The view `view` of the homework whose shader reads as `reading`, rendered on `threads` threads.
fn view(reading: Reading, which: DebugView, threads: usize) -> DebugImage {
    let settings = RenderSettings { width: WIDTH, height: HEIGHT, threads: Some(threads), ..Default::default() };
    render_view(&homework(reading), &settings, which).unwrap()
}

/// What the views show where the pixel's first hit read no texture seen, and where it hit nothing.
const GREY: [u8; 3] = [128, 128, 128];
const DARK_BLUE: [u8; 3] = [0, 0, 96];

/// The column where the mirror sphere is seen and the cube's, on the middle row of the picture.
const MIRROR: (u32, u32) = (WIDTH / 2, HEIGHT / 2 - 4);
const CUBE: (u32, u32) = (WIDTH * 3 / 4 + 2, HEIGHT / 2 - 4);

#[test]
fn the_lookup_view_shows_a_shader_that_swaps_u_and_v_and_the_uv_view_does_not() {
    let uv = view(Reading::AtUv, DebugView::Uv, 1);
    let swapped_uv = view(Reading::AtVu, DebugView::Uv, 1);
    assert!(uv.image == swapped_uv.image, "--view uv is made from the hit: the same for both shaders");

    let right = view(Reading::AtUv, DebugView::Lookup, 1);
    let swapped = view(Reading::AtVu, DebugView::Lookup, 1);
    let (mut read, mut exchanged) = (0, 0);
    for (x, y, right_pixel) in right.image.enumerate_pixels() {
        let [r, g, b] = right_pixel.0;
        let swapped_pixel = swapped.image.get_pixel(x, y).0;
        if [r, g, b] == GREY || [r, g, b] == DARK_BLUE {
            assert_eq!(swapped_pixel, [r, g, b], "pixel {x},{y}: no read, or nothing hit, either way");
            continue;
        }
        read += 1;
        // Where the right shader read is where the hit says it should: the `uv` view's colour.
        let [ur, ug, _] = uv.image.get_pixel(x, y).0;
        assert!(r.abs_diff(ur) <= 1 && g.abs_diff(ug) <= 1, "pixel {x},{y}: read at {r},{g}, uv {ur},{ug}");
        // The swapped shader read at (v, u): red and green exchanged.
        assert_eq!(swapped_pixel, [g, r, b], "pixel {x},{y}");
        exchanged += usize::from(r.abs_diff(g) > 8);
    }
    assert!(read > (WIDTH * HEIGHT / 2) as usize, "the floor and the planet fill most of the picture: {read}");
    assert!(exchanged > read / 2, "u and v differ on most of them: {exchanged} of {read}");
    assert!(right.scale.contains("(read by: Diffuse)"), "{}", right.scale);

    // The mirror reads nothing (its reflection of the floor is not its first hit's read); the cube reads no
    // texture: both grey, named in the scale. The sky is dark blue.
    for (x, y) in [MIRROR, CUBE] {
        assert_eq!(right.image.get_pixel(x, y).0, GREY, "pixel {x},{y}");
    }
    assert_eq!(right.image.get_pixel(WIDTH / 2, 2).0, DARK_BLUE);
    assert!(right.scale.contains("(under: Lambert, Reflection)"), "{}", right.scale);

    // The values read differ too, where the floor's tiles are not symmetric about their diagonal.
    let value = view(Reading::AtUv, DebugView::LookupValue, 1);
    let swapped_value = view(Reading::AtVu, DebugView::LookupValue, 1);
    let differ = value.image.pixels().zip(swapped_value.image.pixels()).filter(|(a, b)| a != b).count();
    assert!(differ > read / 4, "{differ} of {read} pixels read another colour");
}

/// The colour the value view shows is the texture's: where the right shader reads the planet's map, it is
/// the texture's colour there as a picture shows it, not the lit colour of the render.
#[test]
fn the_lookup_value_view_shows_the_colour_the_read_returned() {
    let value = view(Reading::AtUv, DebugView::LookupValue, 1);
    let scene = homework(Reading::AtUv);
    let camera = scene.camera.frame(WIDTH, HEIGHT);
    let world = texture("world.png").unwrap();
    let mut seen = 0;
    for (x, y, pixel) in value.image.enumerate_pixels() {
        let ray = camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5);
        let Some((info, node)) = scene.closest_hit(&ray) else { continue };
        if !std::ptr::eq(node, &scene.nodes[1]) {
            continue;
        }
        let expected = to_srgb8(world.get_tex_color(&ray, &info));
        assert!((0..3).all(|c| pixel.0[c].abs_diff(expected[c]) <= 1), "pixel {x},{y}: {pixel:?} {expected:?}");
        seen += 1;
    }
    assert!(seen > 100, "the planet is seen: {seen} pixels");
}

/// A read through `get_tex_color` called directly is not seen (the scale says so), and the views are the
/// same on one thread and on two.
#[test]
fn the_lookup_views_do_not_see_direct_reads_and_do_not_depend_on_threads() {
    let direct = view(Reading::Direct, DebugView::Lookup, 1);
    assert!(direct.image.pixels().all(|p| p.0 == GREY || p.0 == DARK_BLUE), "no read seen");
    assert!(direct.scale.contains("get_tex_color") && direct.scale.contains("(read by: none seen)"));
    for v in [DebugView::Lookup, DebugView::LookupValue] {
        let one = view(Reading::AtVu, v, 1);
        let two = view(Reading::AtVu, v, 2);
        assert!(one.image == two.image && one.scale == two.scale, "{v:?} differs between 1 and 2 threads");
    }
}
