//! The value fields of a scene: the top-level `varyings` and `provoking_vertex`, and each
//! triangle's per-vertex `varyings` (and a window-space triangle's `w`).

use num_rational::BigRational;
use num_traits::Signed;

use super::json::{Map, Value};
use super::reader::{kind, show, Reader};
use crate::interp::values::{Interpolation, ProvokingVertex, Sampling, Varying, Varyings};
use crate::scene::SceneError;

/// The end of the error for a primitive without the declared varyings' values.
pub(super) const MISSING_TAIL: &str =
    "every triangle, line and clip-space triangle gives their values per vertex (polygons carry none)";

/// The most channels a scene's varyings may have together (OpenGL's
/// `GL_MAX_VARYING_COMPONENTS` is at least 60 and Vulkan's `maxFragmentInputComponents` at
/// least 64; 128 leaves room for both).
pub const MAX_CHANNELS: usize = 128;

impl Reader<'_> {
    /// The top-level `varyings` (each `{"name", "channels", "interpolation", "sampling"}`)
    /// and `provoking_vertex`; none declared when `varyings` is absent.
    pub(super) fn varyings(&self, root: &Map) -> Result<Varyings, SceneError> {
        let provoking = self.named(
            root.get("provoking_vertex"),
            "provoking_vertex",
            ProvokingVertex::default(),
            ProvokingVertex::parse,
            "rule",
            "first or last",
        )?;
        let Some(v) = root.get("varyings") else {
            return Ok(Varyings {
                list: Vec::new(),
                provoking,
            });
        };
        let list = self.each(v, "varyings", MAX_CHANNELS, |item, at| self.varying(item, at))?;
        for (k, v) in list.iter().enumerate() {
            if let Some(first) = list[..k].iter().position(|u| u.name == v.name) {
                return Err(self.err(
                    &format!("varyings[{k}].name"),
                    format!("{:?} is declared twice (also varyings[{first}])", v.name),
                ));
            }
        }
        let varyings = Varyings { list, provoking };
        if varyings.channels() > MAX_CHANNELS {
            return Err(self.err(
                "varyings",
                format!("{} channels in all, at most {MAX_CHANNELS}", varyings.channels()),
            ));
        }
        Ok(varyings)
    }

    fn varying(&self, v: &Value, at: &str) -> Result<Varying, SceneError> {
        let Value::Object(obj) = v else {
            return Err(self.err(
                at,
                format!(
                    "expected an object with \"name\" and \"channels\", found {} {}",
                    kind(v),
                    show(v)
                ),
            ));
        };
        self.known_fields(obj, at, &["name", "channels", "interpolation", "sampling"])?;
        let field = |key: &str| format!("{at}.{key}");
        let name = obj
            .get("name")
            .ok_or_else(|| self.err(&field("name"), "missing (required)".into()))?;
        let name = self.string(name, &field("name"))?;
        if name.is_empty() {
            return Err(self.err(&field("name"), "empty (a varying needs a name)".into()));
        }
        let channels = obj
            .get("channels")
            .ok_or_else(|| self.err(&field("channels"), "missing (required)".into()))?;
        let channels = self.integer(channels, &field("channels"))?;
        let channels = usize::try_from(channels)
            .ok()
            .filter(|c| (1..=MAX_CHANNELS).contains(c))
            .ok_or_else(|| self.err(&field("channels"), format!("{channels} is not in 1..={MAX_CHANNELS}")))?;
        let interpolation = self.named(
            obj.get("interpolation"),
            &field("interpolation"),
            Interpolation::Smooth,
            Interpolation::parse,
            "interpolation",
            "smooth, noperspective or flat",
        )?;
        let sampling = self.named(
            obj.get("sampling"),
            &field("sampling"),
            Sampling::Centre,
            Sampling::parse,
            "sampling point",
            "centre, centroid or sample",
        )?;
        Ok(Varying {
            name: name.to_string(),
            channels,
            interpolation,
            sampling,
        })
    }

    /// The optional name `v` at `field`, read by `parse`: `default` when absent, an error
    /// naming the unknown `what` and the `expected` names otherwise.
    fn named<T>(
        &self,
        v: Option<&Value>,
        field: &str,
        default: T,
        parse: fn(&str) -> Option<T>,
        what: &str,
        expected: &str,
    ) -> Result<T, SceneError> {
        let Some(v) = v else {
            return Ok(default);
        };
        let name = self.string(v, field)?;
        parse(name).ok_or_else(|| self.err(field, format!("unknown {what} {name:?} (expected {expected})")))
    }

    /// The `varyings` field of the primitive object `obj` at `at`: per vertex, every
    /// declared varying's channels concatenated in declaration order. `None` when the
    /// scene declares no varyings (and then the field must be absent).
    pub(super) fn vertex_values<const N: usize>(
        &self,
        obj: &Map,
        at: &str,
        varyings: &Varyings,
    ) -> Result<Option<[Vec<BigRational>; N]>, SceneError> {
        let here = format!("{at}.varyings");
        let given = obj.get("varyings");
        if varyings.list.is_empty() {
            return match given {
                None => Ok(None),
                Some(_) => Err(self.err(
                    &here,
                    "the scene declares no varyings (the top-level \"varyings\" lists their names and channels)".into(),
                )),
            };
        }
        let names: Vec<&str> = varyings.list.iter().map(|v| v.name.as_str()).collect();
        let Some(given) = given else {
            return Err(self.err(
                &here,
                format!(
                    "missing: the scene declares varyings ({}), so {MISSING_TAIL}",
                    names.join(", ")
                ),
            ));
        };
        let Value::Object(given) = given else {
            return Err(self.err(
                &here,
                format!(
                    "expected an object of each varying's values, found {} {}",
                    kind(given),
                    show(given)
                ),
            ));
        };
        self.known_fields(given, &here, &names)?;
        let mut out: [Vec<BigRational>; N] = std::array::from_fn(|_| Vec::new());
        for (k, varying) in varyings.list.iter().enumerate() {
            let field = format!("{here}.{}", varying.name);
            let v = given
                .get(&varying.name)
                .ok_or_else(|| self.err(&field, format!("missing (declared in varyings[{k}])")))?;
            let vertices = self.array(v, &field)?;
            if vertices.len() != N {
                return Err(self.err(
                    &field,
                    format!("expected {N} vertices' values, found {}", vertices.len()),
                ));
            }
            for (i, vertex) in vertices.iter().enumerate() {
                let vf = format!("{field}[{i}]");
                let channels = self.array(vertex, &vf)?;
                if channels.len() != varying.channels {
                    return Err(self.err(
                        &vf,
                        format!(
                            "expected {} channels (varyings[{k}].channels), found {}",
                            varying.channels,
                            channels.len()
                        ),
                    ));
                }
                for (c, value) in channels.iter().enumerate() {
                    out[i].push(self.coordinate(value, &format!("{vf}[{c}]"))?);
                }
            }
        }
        Ok(Some(out))
    }

    /// A window-space triangle's `w` at `at`: three clip-space w, each `> 0` (a triangle
    /// in window space is in front of the eye; one that is not is a clip-space triangle).
    pub(super) fn window_w(
        &self,
        obj: &Map,
        at: &str,
        varyings: &Varyings,
    ) -> Result<Option<[BigRational; 3]>, SceneError> {
        let Some(v) = obj.get("w") else {
            return Ok(None);
        };
        let field = format!("{at}.w");
        if varyings.list.is_empty() {
            return Err(self.err(
                &field,
                "w only serves perspective-correct varyings, and the scene declares none".into(),
            ));
        }
        let list = self.array(v, &field)?;
        if list.len() != 3 {
            return Err(self.err(
                &field,
                format!("expected 3 values (one per vertex), found {}", list.len()),
            ));
        }
        let mut w: [BigRational; 3] = Default::default();
        for (i, value) in list.iter().enumerate() {
            let f = format!("{field}[{i}]");
            w[i] = self.coordinate(value, &f)?;
            if !w[i].is_positive() {
                return Err(self.err(
                    &f,
                    format!(
                        "{} is not positive: a window-space vertex lies in front of the eye (w > 0); \
                         give a triangle that crosses w = 0 as a clip-space triangle, which is clipped",
                        show(value)
                    ),
                ));
            }
        }
        Ok(Some(w))
    }
}
