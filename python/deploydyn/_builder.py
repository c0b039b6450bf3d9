"""ModelBuilder: a model in code, in the model file's terms; `build` gives it to the loader."""
import copy

from deploydyn import _arguments as checked
from deploydyn._element_fields import element_spec
from deploydyn._model import from_dict


def _property(where, key, value):
    """A material's E or alpha: a number, or a table {"temperature_C": [...], "value": [...]}
    (its values checked at `build`, as the loader checks them)."""
    if not isinstance(value, dict):
        return checked.number(where, key, value)
    if set(value) != {"temperature_C", "value"}:
        raise TypeError(f"{where}: {key} as a table needs exactly the keys 'temperature_C' and 'value', "
                        f"not {sorted(value)}")
    return {column: checked.numbers(where, f"{key}.{column}", value[column]) for column in ("temperature_C", "value")}


class ModelBuilder:
    """Builds a model in code, in the model file's terms (docs/model-format.md); SI units.

        b = deploydyn.ModelBuilder("heated bar")
        b.node("A", 0, 0).node("B", 1, 0)
        b.material("steel", E=2e11, alpha=1.2e-5)
        b.bar("1", "A", "B", area=1e-4, material="steel", mass=0.785)
        b.support("A").support("B")
        b.thermal(100)                              # ΔT (°C) of every bar without its own
        b.analysis(type="static", end=1.0, step=0.5)
        model = b.build()

    Functions of time (driver profiles, ΔT, load factors) are a number, the name of a function
    added with `function`, "paper_eq23", or constant/smooth_step/smooth_trapezoid/paper_eq23/
    table/polynomial/harmonic/cosine_ramp/cycloidal/piecewise/sum_of(...). Each method checks
    the types of its arguments (TypeError naming the method and parameter); an element's keys
    are those its type's table in the C++ loader lists (docs/model-format.md), so a new type
    or key is taken with no change here. Values are checked at `build`, which checks
    everything the loader checks.
    """

    def __init__(self, name="", description=""):
        name = checked.text("ModelBuilder", "name", name)
        description = checked.text("ModelBuilder", "description", description)
        self._spec = {"name": name} if name else {}
        if description:
            self._spec["description"] = description

    def _section(self, key, kind=dict):
        return self._spec.setdefault(key, kind())

    def node(self, name, x, y, z=None, mass=None):
        """A node at (x, y[, z]) m, with an optional point mass (kg)."""
        where = "ModelBuilder.node"
        at = [checked.number(where, axis, value) for axis, value in (("x", x), ("y", y), ("z", z))
              if value is not None or axis != "z"]
        spec = at if mass is None else {"at": at, "mass": checked.number(where, "mass", mass)}
        self._section("nodes")[checked.name(where, "name", name)] = spec
        return self

    def material(self, name, E, alpha=0.0, density=None, damping=None, yield_strength=None,
                 specific_heat=None, absorptivity=None, emissivity=None, conductivity=None):
        """E (Pa), alpha (1/°C): each a number, or a table of temperature as data sheets give it,
        {"temperature_C": [20, 200, 400], "value": [2.1e11, 1.95e11, 1.7e11]} (docs/theory.md,
        "Temperature-dependent material properties"); density (kg/m³, for bars that give no mass), damping (material
        damping of its bars, cables and beams, as the model file's mapping: {"ratio": ζ, "frequency":
        f (Hz)}, {"loss_factor": η, "frequency": f} or {"time": τ (s)}), yield_strength (Pa, the
        stress the member checks allow); for an `environment`: specific_heat (J/(kg·K)),
        absorptivity α_s and emissivity ε (both in [0, 1]), conductivity (W/(m·K), for the
        beams' section_gradients)."""
        where = "ModelBuilder.material"
        spec = {"E": _property(where, "E", E), "alpha": _property(where, "alpha", alpha)}
        for key, value in (("density", density), ("yield_strength", yield_strength),
                           ("specific_heat", specific_heat), ("absorptivity", absorptivity),
                           ("emissivity", emissivity), ("conductivity", conductivity)):
            if value is not None:
                spec[key] = checked.number(where, key, value)
        if damping is not None:
            if not isinstance(damping, dict):
                raise TypeError(f"{where}: damping must be a dict such as {{'ratio': 0.02, 'frequency': 10}}, "
                                f"not {type(damping).__name__}")
            spec["damping"] = {checked.name(where, "damping key", k): checked.number(where, f"damping.{k}", v)
                               for k, v in damping.items()}
        self._section("materials")[checked.name(where, "name", name)] = spec
        return self

    def _element(self, where, name, type, given, optional, more, type_key=True):
        """Adds element `name` of `type`: `given` (the method's required parameters, checked
        even when None), `optional` (its keyword parameters, left out when None) and `more`
        (other keys by name), all checked against the type's field table."""
        for key in more:
            if key in given or key in optional:
                raise TypeError(f"{where}: {key!r} is a parameter of its own, not for **fields")
        fields = {**given, **{k: v for k, v in optional.items() if v is not None}, **more}
        spec = element_spec(where, type, fields)
        self._section("elements")[checked.name(where, "name", name)] = (
            {"type": type, **spec} if type_key else spec)
        return self

    def bar(self, name, node_a, node_b, area, material, mass=None, length=None, dT=None,
            **fields):
        """A bar between two nodes: area (m²), mass (kg; default density·area·L0), length
        (m, the reference length L0; default the nodes' distance), dT (its own ΔT(t), °C); other
        keys of a bar (e.g. inertia, m⁴) by name, as docs/model-format.md lists them."""
        where = "ModelBuilder.bar"
        nodes = [checked.name(where, "node_a", node_a), checked.name(where, "node_b", node_b)]
        return self._element(where, name, "bar", {"nodes": nodes, "area": area, "material": material},
                             {"mass": mass, "length": length, "dT": dT}, fields, type_key=False)

    def beam(self, name, node_a, node_b, area, inertia_z, material, shear_factor=None,
             shear_modulus=None, height_y=None, dT_gradient_y=None, mass=None, length=None,
             dT=None, **fields):
        """A geometrically exact beam between two nodes (docs/theory.md, "Beams"): area (m²),
        inertia_z (m⁴, in-plane bending in 2D), shear_factor (default 5/6), shear_modulus (Pa,
        default E/2.6), height_y (m) and dT_gradient_y (T(+y) − T(−y), °C, a function of t),
        mass, length, dT as for `bar`. 3D keys (inertia_y, torsion, orientation, height_z,
        dT_gradient_z) and the other keys of a beam go by name, among them its sectional values
        as engineers give them: mass_per_length (kg/m), rotary_inertia_per_length (kg·m; 3D
        [J_xx, J_yy, J_zz] in the local frame or the full tensor [J_xx, J_yy, J_zz, J_xy, J_xz,
        J_yz], 2D J_zz), shear_stiffness (N; 3D [GA_y, GA_z], 2D GA_y), axial_stiffness (N),
        bending_stiffness (N·m²; 3D [EI_y, EI_z], 2D EI_z) and torsional_stiffness (N·m², 3D);
        the full sectional_stiffness (the rows of C about the axis: 36 numbers in 3D, 9 in 2D)
        and centroid_offset (m; 3D local [y, z], 2D the number y); in 3D also the local [y, z]
        (m) of the shear_centre_offset and mass_centroid_offset, and the sectional_mass (36
        numbers, the rows of the rigid section's 6 × 6 mass matrix about the axis, in place of
        mass_per_length, rotary_inertia_per_length and mass_centroid_offset). Its nodes carry a
        rotation: clamp one with support(node, fix=["x", "y", "rotation"])."""
        where = "ModelBuilder.beam"
        nodes = [checked.name(where, "node_a", node_a), checked.name(where, "node_b", node_b)]
        return self._element(
            where, name, "beam",
            {"nodes": nodes, "area": area, "inertia_z": inertia_z, "material": material},
            {"shear_factor": shear_factor, "shear_modulus": shear_modulus, "height_y": height_y,
             "mass": mass, "length": length, "dT_gradient_y": dT_gradient_y, "dT": dT}, fields)

    def cable(self, name, node_a, node_b, area, material, rest_length=None, pretension=None,
              mass=None, dT=None, **fields):
        """A tension-only cable between two nodes (docs/theory.md, "Cables"): area (m²),
        rest_length (m, a number or a function of t: a winch; default the nodes' distance) or
        pretension (N, the initial cable's tension at ΔT = 0; not both), mass (kg; default
        density·area·L0(0)), dT (its own ΔT(t), °C); other keys of a cable (e.g. break_load, N)
        by name."""
        where = "ModelBuilder.cable"
        nodes = [checked.name(where, "node_a", node_a), checked.name(where, "node_b", node_b)]
        return self._element(where, name, "cable", {"nodes": nodes, "area": area, "material": material},
                             {"pretension": pretension, "mass": mass, "rest_length": rest_length,
                              "dT": dT}, fields)

    def hinge(self, name, nodes=None, rotation_nodes=None, stiffness=None, rest_angle=None,
              damping=None, friction=None, pin_radius=None, stop_min=None, stop_max=None,
              latch=None, axis=None, **fields):
        """A hinge (docs/theory.md, "Hinges") on the angle at H between bars, nodes [A, H, B],
        or between two 2D beam nodes, rotation_nodes [A, B]: a torsion spring `stiffness`
        (N·m/rad) unloaded at `rest_angle` (rad), a damper `damping` (N·m·s/rad), Coulomb
        `friction` μ with `pin_radius` (m) pressed by the bar A–H's axial force, end stops
        `stop_min`/`stop_max` and a `latch` angle (rad); `axis` [ax, ay, az] in 3D; other keys
        of a hinge by name."""
        return self._element("ModelBuilder.hinge", name, "hinge", {},
                             {"nodes": nodes, "rotation_nodes": rotation_nodes,
                              "stiffness": stiffness, "rest_angle": rest_angle, "damping": damping,
                              "friction": friction, "pin_radius": pin_radius, "stop_min": stop_min,
                              "stop_max": stop_max, "latch": latch, "axis": axis}, fields)

    def element(self, name, type, **fields):
        """An element of any type (`type`, e.g. "bar"), its keys as the model file spells them
        (docs/model-format.md). The keys are those of the type's table in the C++ loader: an
        unknown type is a ValueError, an unknown key, a missing required one or a value of the
        wrong kind a TypeError naming it; the loader checks the values at `build`."""
        where = "ModelBuilder.element"
        return self._element(where, name, checked.name(where, "type", type), {}, {}, fields)

    def cross_section(self, name, shape, **dimensions):
        """A named cross-section that bars, beams and cables take with `section="name"`
        (docs/model-format.md, `sections`), dimensions in metres: shape "circular_tube"
        (outer_diameter, wall_thickness), "rectangular_tube" (width, height, wall_thickness),
        "circle" (diameter) or "rectangle" (width, height). Area, second moments, torsion
        constant and section moduli follow from it. Checked at `build`."""
        where = "ModelBuilder.cross_section"
        spec = {"shape": checked.text(where, "shape", shape)}
        for key, value in dimensions.items():
            spec[key] = checked.number(where, key, value)
        self._section("sections")[checked.name(where, "name", name)] = spec
        return self

    def member(self, name, elements, buckling_length_factor=None, slack=None):
        """Elements of one type that form one structural part, which the member checks treat as
        one (docs/model-format.md, `members`): a tube meshed as several beams, joined end to end.
        Bars and beams: `buckling_length_factor` K (> 0; a 3D beam member may give [K_y, K_z],
        K about the section's local y and z); not given, K follows from the member's ends.
        Cables: `slack` "allowed" (default) or "forbidden" (going slack fails the verdict)."""
        where = "ModelBuilder.member"
        spec = {"elements": checked.names(where, "elements", elements)}
        if buckling_length_factor is not None:
            if checked.is_number(buckling_length_factor):
                spec["buckling_length_factor"] = checked.number(where, "buckling_length_factor", buckling_length_factor)
            else:
                spec["buckling_length_factor"] = checked.numbers(where, "buckling_length_factor", buckling_length_factor)
        if slack is not None:
            spec["slack"] = checked.text(where, "slack", slack)
        self._section("members")[checked.name(where, "name", name)] = spec
        return self

    def checks(self, clearance=None, clearance_m=None):
        """The clearance watch (docs/model-format.md, `checks`): `clearance` False turns it off;
        `clearance_m` (m) the least distance members must keep, a violation failing the verdict."""
        where = "ModelBuilder.checks"
        spec = self._section("checks")
        if clearance is not None:
            if not isinstance(clearance, bool):
                raise TypeError(f"{where}: clearance must be True or False, not {checked.shown(clearance)}")
            spec["clearance"] = clearance
        if clearance_m is not None:
            spec["clearance_m"] = checked.number(where, "clearance_m", clearance_m)
        return self

    def support(self, node, fix=None, axis=None, offset=None):
        """Fix a node's coordinates: all axes, or those in `fix` (e.g. ["y"], or "y"); "rotation"
        in `fix` clamps a beam's node. On a 3D beam node, `axis` [ax, ay, az] makes it a hinge
        to ground (the frame turns about that global axis only) and `offset` [ox, oy, oz] (m)
        holds the point x + R·offset instead of the node (docs/model-format.md, `supports`)."""
        where = "ModelBuilder.support"
        spec = {"node": checked.name(where, "node", node)}
        if fix is not None:
            axes = [fix] if isinstance(fix, str) else fix
            if not isinstance(axes, (list, tuple)) or not all(isinstance(a, str) for a in axes):
                raise TypeError(f"{where}: fix must be a list of axis names (\"x\", \"y\", "
                                f"\"z\"), not {checked.shown(fix)}")
            spec["fix"] = list(axes)
        if axis is not None:
            spec["axis"] = checked.numbers(where, "axis", axis)
        if offset is not None:
            spec["offset"] = checked.numbers(where, "offset", offset)
        self._section("supports", list).append(spec)
        return self

    def bar_angle_driver(self, name, element, profile, pivot=None, reading="angular_velocity",
                         axis=None):
        """Turn bar `element` about `pivot` (default its first node); reading
        "angular_velocity" (profile ω(t), rad/s) or "angle" (rad)."""
        where = "ModelBuilder.bar_angle_driver"
        spec = {"type": "bar_angle", "element": checked.name(where, "element", element),
                "profile": checked.time_function(where, "profile", profile),
                "reading": checked.text(where, "reading", reading)}
        if pivot is not None:
            spec["pivot"] = checked.name(where, "pivot", pivot)
        if axis is not None:
            spec["axis"] = checked.numbers(where, "axis", axis)
        self._section("drivers")[checked.name(where, "name", name)] = spec
        return self

    def joint(self, name, node_a, node_b, type="pin", axis=None, arms=None, offsets=None):
        """A joint: nodes `node_a` and `node_b` (at one initial position) keep one position.
        `type` "pin": in 3D between beam nodes `axis` [ax, ay, az] is required and stays
        common; "ball": positions only; "universal" (3D beam nodes): `arms` [u, w], the cross's
        arm fixed in A's frame and the one in B's, perpendicular. `offsets` [o_A, o_B] (m):
        the joint acts at x + R·o of each node (3D beam nodes; docs/model-format.md, `joints`)."""
        where = "ModelBuilder.joint"
        spec = {"type": checked.text(where, "type", type),
                "nodes": [checked.name(where, "node_a", node_a), checked.name(where, "node_b", node_b)]}
        if axis is not None:
            spec["axis"] = checked.numbers(where, "axis", axis)
        for key, pair in (("arms", arms), ("offsets", offsets)):
            if pair is None:
                continue
            if isinstance(pair, (str, bytes)) or not hasattr(pair, "__iter__") or len(list(pair)) != 2:
                raise TypeError(f"{where}: {key} must be two vectors [[x, y, z], [x, y, z]], "
                                f"not {checked.shown(pair)}")
            spec[key] = [checked.numbers(where, f"{key}[{i}]", v) for i, v in enumerate(pair)]
        self._section("joints")[checked.name(where, "name", name)] = spec
        return self

    def ball_joint(self, name, node_a, node_b, offsets=None):
        """A spherical joint: the two nodes (or their offset points) keep one position."""
        return self.joint(name, node_a, node_b, type="ball", offsets=offsets)

    def universal_joint(self, name, node_a, node_b, arms, offsets=None):
        """A Cardan joint between 3D beam nodes: one position, and the cross's arms `arms`
        [u, w] (u fixed in A's frame, w in B's, perpendicular) stay perpendicular."""
        return self.joint(name, node_a, node_b, type="universal", arms=arms, offsets=offsets)

    def revolute_driver(self, name, joint=None, profile=None, reading="angular_velocity", support=None):
        """Turn node B of pin `joint` relative to node A about the joint's axis (nodes with
        rotations: beams), or, with `support` (a node name) in place of `joint`, that node
        about the axis of its hinge to ground (3D: a support with `axis`; 2D: rz free);
        reading "angular_velocity" (rad/s) or "angle" (rad)."""
        where = "ModelBuilder.revolute_driver"
        if (joint is None) == (support is None):
            raise TypeError(f"{where}: give either joint (a pin between two nodes) or support (a "
                            f"node's hinge to ground), not {'both' if joint is not None else 'neither'}")
        if profile is None:
            raise TypeError(f"{where}: profile is required")
        spec = {"type": "revolute"}
        if joint is not None:
            spec["joint"] = checked.name(where, "joint", joint)
        else:
            spec["support"] = checked.name(where, "support", support)
        spec["profile"] = checked.time_function(where, "profile", profile)
        spec["reading"] = checked.text(where, "reading", reading)
        self._section("drivers")[checked.name(where, "name", name)] = spec
        return self

    def hinge_angle_driver(self, name, node_a, hinge, node_b, profile, axis=None,
                           reading="angular_velocity"):
        """Drive the angle at `hinge` from hinge→`node_a` to hinge→`node_b`, about `axis`
        (required in 3D; z in 2D), from its initial value; reading "angular_velocity" (rad/s)
        or "angle" (rad). Fixes that one angle only."""
        where = "ModelBuilder.hinge_angle_driver"
        spec = {"type": "hinge_angle",
                "nodes": [checked.name(where, "node_a", node_a), checked.name(where, "hinge", hinge),
                          checked.name(where, "node_b", node_b)],
                "profile": checked.time_function(where, "profile", profile),
                "reading": checked.text(where, "reading", reading)}
        if axis is not None:
            spec["axis"] = checked.numbers(where, "axis", axis)
        self._section("drivers")[checked.name(where, "name", name)] = spec
        return self

    def coordinate_driver(self, name, node, direction, profile, reading="velocity"):
        """Prescribe coordinate `direction` ("x", "y", "z") of `node`; reading "velocity"
        (m/s) or "displacement" (m)."""
        where = "ModelBuilder.coordinate_driver"
        self._section("drivers")[checked.name(where, "name", name)] = {
            "type": "coordinate", "node": checked.name(where, "node", node),
            "direction": checked.text(where, "direction", direction),
            "profile": checked.time_function(where, "profile", profile),
            "reading": checked.text(where, "reading", reading)}
        return self

    def load(self, node, force=None, factor=None, moment=None):
        """A nodal force (N) and, on a beam's node, a moment (N·m): in 2D a number
        (counter-clockwise about z), in 3D a vector [mx, my, mz] fixed in space; both times
        factor(t) (default 1)."""
        where = "ModelBuilder.load"
        spec = {"node": checked.name(where, "node", node)}
        if force is not None:
            spec["force"] = checked.numbers(where, "force", force)
        if moment is not None:
            spec["moment"] = (checked.number(where, "moment", moment) if checked.is_number(moment)
                              else checked.numbers(where, "moment", moment))
        if factor is not None:
            spec["factor"] = checked.time_function(where, "factor", factor)
        self._section("loads", list).append(spec)
        return self

    def function(self, name, spec):
        """A named function of time, usable by name in profiles, dT and factors."""
        where = "ModelBuilder.function"
        self._section("functions")[checked.name(where, "name", name)] = checked.time_function(where, "spec", spec)
        return self

    def thermal(self, dT=None, reference_temperature_C=None):
        """ΔT(t) (°C) of every bar without its own; reference_temperature_C: the stress-free
        temperature T_ref (°C, default 20) at which the materials' temperature tables are read
        for ΔT = 0."""
        if dT is not None or reference_temperature_C is None:  # thermal(None) or thermal(): dT is wrong
            self._section("thermal")["dT"] = checked.time_function("ModelBuilder.thermal", "dT", dT)
        if reference_temperature_C is not None:
            self._section("thermal")["reference_temperature_C"] = checked.number(
                "ModelBuilder.thermal", "reference_temperature_C", reference_temperature_C)
        return self

    def environment(self, type, **keys):
        """The members' temperatures from their surroundings (docs/theory.md, "Temperatures from
        the environment"), as the model file's `environment`: type "orbit" (sun_direction,
        solar_constant, sink_temperature, eclipses, penumbra) or "ground" (latitude, longitude,
        start, utc_offset, up, north, direct_normal, diffuse, air_temperature, sky_temperature,
        convection), and reference_temperature and initial_temperature (K), shadows ({"every",
        "samples_along", "samples_across"} or True) and section_gradients (True: beams bend away from
        the sun). Temperatures in K, fluxes in W/m². Not with `thermal`. Checked at `build`
        (InputError names environment.<key>)."""
        where = "ModelBuilder.environment"
        self._spec["environment"] = {"type": checked.text(where, "type", type), **checked.plain(keys, "environment", where)}
        return self

    def gravity(self, *g):
        """Gravity (m/s²), one component per axis: gravity(0, -9.81) or gravity([0, -9.81])."""
        values = g[0] if len(g) == 1 and not checked.is_number(g[0]) else g
        self._spec["gravity"] = checked.numbers("ModelBuilder.gravity", "g", values)
        return self

    def spin(self, rate, centre, axis=None):
        """Start a dynamic run spinning rigidly at `rate` ω (rad/s) about an axis through `centre`
        (m): about z in 2D, about `axis` [ax, ay, az] in 3D (docs/model-format.md,
        `initial_velocities`). Node velocities (`node_velocity`) add to it; the run makes the sum
        consistent with the constraints."""
        where = "ModelBuilder.spin"
        spec = {"rate": checked.number(where, "rate", rate), "centre": checked.numbers(where, "centre", centre)}
        if axis is not None:
            spec["axis"] = checked.numbers(where, "axis", axis)
        self._section("initial_velocities")["spin"] = spec
        return self

    def node_velocity(self, node, velocity):
        """Start a dynamic run with `node` moving at `velocity` [vx, vy(, vz)] (m/s), added to a
        `spin`'s (docs/model-format.md, `initial_velocities`)."""
        where = "ModelBuilder.node_velocity"
        self._section("initial_velocities").setdefault("nodes", []).append(
            {"node": checked.name(where, "node", node), "velocity": checked.numbers(where, "velocity", velocity)})
        return self

    def analysis(self, **options):
        """Analysis options as in the file: type ("static"/"dynamic"/"modal"), end, end_when
        ("end_time"/"all_latched"/"settled"), step, output_interval, load_steps, mass,
        integrator={...}, newton={...}, rayleigh={"alpha", "beta"} or {"ratios": [ζ1, ζ2],
        "frequencies": [f1, f2]} (Rayleigh damping), settle={"kinetic_energy", "rate", "hold",
        "node"} (with end_when="settled"). Their values are checked at `build` (InputError names
        analysis.<option>)."""
        self._section("analysis").update(checked.plain(options, "analysis", "ModelBuilder.analysis"))
        return self

    def output(self, **options):
        """Output options as in the file: history, summary (file names), vtk (bool), select={nodes,
        elements, quantities} (what history.csv holds: names or patterns, and column families such
        as "position", "displacement", "force", "stress", "reaction"). Checked at `build`."""
        self._section("output").update(checked.plain(options, "output", "ModelBuilder.output"))
        return self

    def to_dict(self):
        """The model file's content as a dict (a copy)."""
        return copy.deepcopy(self._spec)

    def build(self, overrides=None):
        """Check and return the Model; InputError names the field of any mistake."""
        return from_dict(self._spec, overrides=overrides)
