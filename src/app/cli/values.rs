//! The lesson's choices as command-line values: `clap::ValueEnum` for the enums of the lesson that an option
//! takes (`--fresnel exact`, `--wrap mirror`, `--tonemap reinhard`, ...). The lesson layer knows nothing of the
//! command line; its types get their command-line names here, so that an example (and a student's copy of one)
//! writes `#[arg(long, value_enum, default_value_t = FresnelMode::Schlick)]` as it always has. Each value has
//! the name the command line spells and `--help` lists, and the help `--help` shows beside it.

use crate::files::encoding::Encoding;
use crate::instruments::tone_mapping::ToneMap;
use crate::lesson::beyond::Step;
use crate::lesson::bitmap::{Filter, Wrap};
use crate::lesson::camera::FovAxis;
use crate::lesson::environment::CubemapLayout;
use crate::lesson::sampling::DiscSampler;
use crate::lesson::spectral::{GamutMapping, Illuminant, SpectralMode};
use crate::lesson::texture::FresnelMode;
use clap::builder::PossibleValue;

/// `value_enums! { Type { Variant = "name": "help", ... } ... }`: `clap::ValueEnum` for each type, its values
/// in the order given (the order `--help` lists them in).
macro_rules! value_enums {
    ($($type:ident { $($variant:ident = $name:literal: $help:literal,)+ })+) => {$(
        impl clap::ValueEnum for $type {
            fn value_variants<'a>() -> &'a [Self] {
                &[$($type::$variant),+]
            }

            fn to_possible_value(&self) -> Option<PossibleValue> {
                Some(match self {
                    $($type::$variant => PossibleValue::new($name).help($help),)+
                })
            }
        }
    )+};
}

/// The steps beyond the slides by their names, each with its one-line summary.
impl clap::ValueEnum for Step {
    fn value_variants<'a>() -> &'a [Self] {
        &Step::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()).help(self.summary()))
    }
}

value_enums! {
    Wrap {
        Repeat = "repeat": "The image tiles the plane",
        Mirror = "mirror": "Every other tile is mirrored, so neighbouring tiles meet without a seam",
        Clamp = "clamp": "Coordinates stick to the edge pixels",
    }
    Filter {
        Nearest = "nearest": "The texel the point falls in: blocky when magnified",
        Bilinear = "bilinear": "A distance-weighted mix of the four texels around the point",
    }
    ToneMap {
        Clamp = "clamp": "Every channel clamped to 1, as the course does: exact below 1, white above",
        Reinhard = "reinhard": "The luminance L becomes L / (1 + L), the colour scaled with it: nothing reaches \
            white, bright skies keep their clouds; everything is darker, so pair it with a positive `--exposure`",
    }
    Encoding {
        Srgb = "srgb": "sRGB (correct): an 8-bit texture is decoded to light before it is lit, and the light \
            is encoded before it is written",
        Raw = "raw": "The course's lecture-6 program: a code over 255 is the light itself, in the files read and \
            the picture written, with no curve (lighting in the wrong space, as the class's pictures show it)",
    }
    CubemapLayout {
        OpenGl = "opengl": "OpenGL's and Direct3D's: the skyboxes found on the web, and the workbook's own \
            `sky_cubemap`",
        Course = "course": "The course's: `negz` turned by 180° against OpenGL's. The course's cube maps and \
            scene files",
    }
    FovAxis {
        Diagonal = "diagonal": "Corner to corner, as the course measures it: a change of aspect ratio changes \
            both extents",
        Vertical = "vertical": "Top to bottom: the vertical extent stays when the aspect ratio changes (most \
            renderers' choice)",
        Horizontal = "horizontal": "Left to right: the horizontal extent stays when the aspect ratio changes",
    }
    FresnelMode {
        Schlick = "schlick": "Schlick's approximation, as on the slide",
        Exact = "exact": "The exact Fresnel equations for unpolarised light",
    }
    DiscSampler {
        Random = "random": "Independent uniform points (the slide's sampler)",
        Stratified = "stratified": "A randomly shifted (0, 2)-sequence mapped concentrically to the disc, one per \
            shading point",
        Joint = "joint": "One randomly shifted (0, 2)-sequence per pixel, shared out between its camera samples",
    }
    SpectralMode {
        Passes = "passes": "The slide's method: `--wavelengths` K full passes, one per band, added with the \
            bands' colours",
        Sampled = "sampled": "Spectral sampling: one pass in which every anti-aliasing sample of a pixel carries \
            its own band of the spectrum (spp bands per pixel, wavelength jittered within the band)",
        Hero = "hero": "Hero-wavelength sampling: every anti-aliasing sample carries `--wavelengths` wavelengths, \
            evenly spread; its path is traced once, and again for each of the other wavelengths only if it meets \
            dispersive glass",
    }
    Illuminant {
        D65 = "d65": "CIE standard illuminant D65, average daylight: the white of sRGB, so a white light stays \
            white",
        EqualEnergy = "equal-energy": "The same power at every wavelength (CIE illuminant E): in sRGB a little \
            pink, (1.20, 0.95, 0.91)",
    }
    GamutMapping {
        Clip = "clip": "Negative channels become 0, the others stay: the usual choice for spectral colours, which \
            keeps the rainbow saturated (and makes it a little lighter than the light it shows)",
        Fit = "fit": "Grey of the same luminance is mixed in until no channel is negative: keeps luminance and \
            hue, desaturates the rainbow",
    }
}
