//! The made-up submissions of a class, one of each kind, all copies of `examples/refract.rs` (the teacher's
//! reference), for the class test (`teacher/tests/class.rs`) and the measurement of a class of sixty
//! (`teacher/benches/class_of_sixty.rs`).

/// The workbook's refraction example, with `from` replaced by `to` (which must be there), and `more`
/// added at the end.
fn refract_with(from: &str, to: &str, more: &str) -> String {
    let example = std::fs::read_to_string(teacher::workbook().join("examples/refract.rs")).expect("the example");
    assert!(example.contains(from), "examples/refract.rs has no {from:?}");
    format!("{}{more}", example.replacen(from, to, 1))
}

/// A copy of the example whose glass is the shader `name`, defined in `definition`.
fn with_shader(name: &str, definition: &str) -> String {
    refract_with(
        "let glass = Arc::new(Refraction::new(self.ior, 0.95));",
        &format!("let glass = Arc::new({name});"),
        definition,
    )
}

/// The start of the example's `scene`, where a student's first line goes.
const SCENE: &str = "    fn scene(&self) -> Result<Scene> {\n";

/// The submissions, by student: their names and their files' text.
pub fn submissions() -> Vec<(&'static str, String)> {
    vec![
        ("alice", refract_with("", "", "")),
        ("bob", refract_with("default_value_t = 1.5", "default_value_t = 1.33", "")),
        ("carol", refract_with("scene.max_depth = 8;", "scene.max_depth = eight;", "")),
        (
            "dave",
            refract_with(
                SCENE,
                &format!(
                    "{SCENE}        if self.ior > 0.0 {{\n            panic!(\"the glass is not ready\");\n        }}\n"
                ),
                "",
            ),
        ),
        (
            "erin",
            refract_with(
                SCENE,
                &format!("{SCENE}        while self.ior > 0.0 {{\n            std::hint::spin_loop();\n        }}\n"),
                "",
            ),
        ),
        (
            "frank",
            with_shader(
                "Runaway",
                "\n/// A mirror averaging a billion rays at every hit.\nstruct Runaway;\n\nimpl Shader for Runaway {\n    \
                 fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {\n        \
                 let normal = faceforward(info.normal, ray.dir);\n        let mut sum = Color::BLACK;\n        \
                 for _ in 0..1_000_000_000u32 {\n            sum += ctx.raytrace(&ray.spawn(info, reflect(ray.dir, normal), 1.0));\n        \
                 }\n        sum * 1e-9\n    }\n}\n",
            ),
        ),
        (
            "grace",
            with_shader(
                "Dark",
                "\n/// A shader whose light is 0/0.\nstruct Dark;\n\nimpl Shader for Dark {\n    \
                 fn shade(&self, _ray: &Ray, info: &IntersectionInfo, _ctx: &mut TraceContext) -> Color {\n        \
                 let nothing = info.distance - info.distance;\n        Color::gray(nothing / nothing)\n    }\n}\n",
            ),
        ),
        (
            "heidi",
            with_shader(
                "Brighter",
                "\n/// A mirror that gives back half as much light again as it receives.\nstruct Brighter;\n\n\
                 impl Shader for Brighter {\n    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {\n        \
                 let normal = faceforward(info.normal, ray.dir);\n        \
                 ctx.raytrace(&ray.spawn(info, reflect(ray.dir, normal), 1.5)) * 1.5\n    }\n}\n",
            ),
        ),
        ("kate", refract_with("const DEFAULT_SPP: u32 = 4;", "const DEFAULT_SPP: u32 = 20_000;", "")),
        ("ken", refract_with("Refraction::new(self.ior, 0.95)", "Refraction::new(self.ior, 9.0)", "")),
        ("lena", refract_with("Color::new(1.0, 0.96, 0.9), 60000.0)", "Color::new(1.0, 0.96, 0.9), f32::NAN)", "")),
        (
            "mallory",
            "//! A picture written by hand, its write never finished.\n\
             use std::io::Write;\n\n\
             fn main() {\n    \
                 let args: Vec<String> = std::env::args().collect();\n    \
                 let picture = args.iter().position(|a| a == \"-o\").and_then(|i| args.get(i + 1)).expect(\"-o\");\n    \
                 let _ = lecture6::files::output::save_atomically(std::path::Path::new(picture), |file| {\n        \
                     file.write_all(&[0u8; 1 << 20])?;\n        \
                     file.flush()?;\n        \
                     loop {\n            std::hint::spin_loop();\n        }\n    \
                 });\n\
             }\n"
                .to_string(),
        ),
        (
            "ivan",
            refract_with(
                SCENE,
                &format!(
                    "{SCENE}        let hog = vec![1u8; 3 << 30];\n        if hog[hog.len() - 1] == 0 {{\n            \
                     return Err(Error::parameter(\"--ior\", self.ior, \"never\"));\n        }}\n"
                ),
                "",
            ),
        ),
    ]
}
