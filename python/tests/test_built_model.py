"""Models built in code: every builder part reaches the solver, and answers match hand values."""
import math

import numpy as np
import pytest

import deploydyn

E = 2.0e11      # Pa
AREA = 1.0e-4   # m²
ALPHA = 1.2e-5  # 1/°C


def test_heated_bar_between_pins_carries_minus_EA_alpha_dT():
    dT = 100.0
    model = (deploydyn.ModelBuilder("heated bar")
             .node("A", 0, 0).node("B", 1.5, 0)
             .material("steel", E=E, alpha=ALPHA)
             .bar("1", "A", "B", area=AREA, material="steel", mass=1.2)
             .support("A").support("B")
             .thermal(deploydyn.smooth_step(0, 0, 1, dT))
             .analysis(type="static", end=1.0, step=0.25)
             .build())
    result = model.run(check=True)
    # The pins hold the length: no total strain, mechanical strain −αΔT, force −EAαΔT.
    assert result["force.1"][-1] == pytest.approx(-E * AREA * ALPHA * dT, rel=1e-12)
    np.testing.assert_allclose(result["strain.1"], 0.0, atol=1e-15)
    assert result["mstrain.1"][-1] == pytest.approx(-ALPHA * dT, rel=1e-12)
    # Halfway along the smooth step ΔT is half of it.
    assert result["force.1"][2] == pytest.approx(-E * AREA * ALPHA * dT / 2, rel=1e-12)
    assert result.summary["elements"]["1"]["force"]["min"] == pytest.approx(-E * AREA * ALPHA * dT)


def test_a_bar_with_its_own_dT_and_a_roller_expands_freely():
    model = (deploydyn.ModelBuilder("free bar")
             .node("A", 0, 0).node("B", 2, 0)
             .material("steel", E=E, alpha=ALPHA, density=7850)
             .bar("1", "A", "B", area=AREA, material="steel", dT=50)
             .support("A").support("B", fix=["y"])
             .thermal(-20)                                # bars without their own: none here
             .analysis(type="static", end=1.0, step=1.0)
             .build())
    assert model.temperature_changes() == {"1": 50.0}
    assert model.elements["1"]["mass"] == pytest.approx(7850 * AREA * 2)
    result = model.run(check=True)
    assert abs(result["force.1"][-1]) < 1e-6
    # Green–Lagrange: ε = ((l/L0)² − 1)/2 = αΔT.
    assert result["x.B"][-1] == pytest.approx(2 * math.sqrt(1 + 2 * ALPHA * 50), rel=1e-12)
    assert result["strain.1"][-1] == pytest.approx(ALPHA * 50, rel=1e-9)


@pytest.mark.parametrize("profile, reading, end, angle", [
    (deploydyn.table([(0, 0), (1, math.pi / 2), (2, math.pi / 2)]), "angle", 1.0, math.pi / 2),
    (deploydyn.smooth_step(0, 0, 2, 0.8), "angle", 1.0, 0.4),
    (deploydyn.constant(0.5), "angular_velocity", 2.0, 1.0),
    (0.25, "angular_velocity", 2.0, 0.5),
    (deploydyn.paper_eq23(), "angular_velocity", 5.0, 1.46),
    ("paper_eq23", "angular_velocity", 5.0, 1.46),
    (deploydyn.smooth_trapezoid(1.0, (0, 1), (2, 3)), "angular_velocity", 3.0, 2.0),
    ("omega", "angular_velocity", 3.0, 2.0),
])
def test_driver_profiles_turn_a_crank(profile, reading, end, angle):
    model = (deploydyn.ModelBuilder("crank")
             .node("A", 0, 0).node("B", 1, 0)
             .material("steel", E=E)
             .bar("crank", "A", "B", area=AREA, material="steel", mass=1.0)
             .support("A")
             .function("omega", deploydyn.smooth_trapezoid(1.0, (0, 1), (2, 3)))
             .bar_angle_driver("motor", element="crank", pivot="A", profile=profile,
                               reading=reading)
             .analysis(type="static", end=end, step=end / 50)
             .build())
    result = model.run(check=True)
    reached = math.atan2(result["y.B"][-1], result["x.B"][-1])
    assert reached == pytest.approx(angle, abs=1e-9)


def test_loaded_two_bar_truss_matches_statics():
    load = 1000.0  # N, down at the apex
    half_span, rise = 1.0, 0.5
    model = (deploydyn.ModelBuilder("two-bar truss")
             .node("A", -half_span, 0).node("B", half_span, 0).node("C", 0, rise, mass=2.0)
             .material("steel", E=E)
             .bar("1", "A", "C", area=AREA, material="steel", mass=1.0)
             .bar("2", "B", "C", area=AREA, material="steel", mass=1.0)
             .support("A").support("B")
             .load("C", [0, -load], factor=deploydyn.smooth_step(0, 0, 1, 1))
             .gravity(0, 0)
             .analysis(type="static", end=1.0, step=0.1)
             .build())
    result = model.run(check=True)
    sin = rise / math.hypot(half_span, rise)
    for bar in ("force.1", "force.2"):        # compression; the apex sags a little
        assert result[bar][-1] == pytest.approx(-load / (2 * sin), rel=1e-3)


def test_builder_mistake_names_the_field_not_a_line():
    builder = (deploydyn.ModelBuilder("bad")
               .node("A", 0, 0).node("B", 1, 0)
               .material("steel", E=E)
               .bar("1", "A", "B", area=-1.0, material="steel", mass=1.0))
    with pytest.raises(ValueError) as error:
        builder.build()
    assert str(error.value) == "<model 'bad' built in Python>: elements.1.area: must be positive (m²), got -1.0"
    assert error.value.field == "elements.1.area"
    assert error.value.line is None
    builder.bar("1", "A", "Q", area=1e-4, material="steel", mass=1.0)
    with pytest.raises(deploydyn.InputError, match=r"elements\.1\.nodes.*unknown node 'Q'"):
        builder.build()


def test_from_dict_is_the_file_layout():
    spec = {"nodes": {"A": [0, 0], "B": [1, 0]},
            "materials": {"m": {"E": 1e9}},
            "elements": {"1": {"nodes": ["A", "B"], "area": 1e-4, "material": "m", "mass": 1}},
            "supports": [{"node": "A"}, {"node": "B"}],
            "analysis": {"type": "static", "end": 1, "step": 1}}
    model = deploydyn.from_dict(spec, overrides={"analysis.end": 2})
    assert model.analysis["end"] == 2.0
    assert model.run(check=True).values.shape[0] == 3


def test_an_element_by_type_is_the_same_bar():
    def heated(add_bar):
        builder = (deploydyn.ModelBuilder("heated bar")
                   .node("A", 0, 0).node("B", 1.5, 0)
                   .material("steel", E=E, alpha=ALPHA))
        add_bar(builder)
        return (builder.support("A").support("B").thermal(100)
                .analysis(type="static", end=1.0, step=0.5).build())
    by_method = heated(lambda b: b.bar("1", "A", "B", area=AREA, material="steel", mass=1.2))
    by_type = heated(lambda b: b.element("1", "bar", nodes=["A", "B"], area=AREA,
                                         material="steel", mass=1.2))
    assert by_type.elements == by_method.elements
    assert by_type.elements["1"]["type"] == "bar"
    assert by_type.to_yaml() == by_method.to_yaml()


def test_clamped_beam_under_a_through_section_gradient_carries_EI_alpha_dTg_over_h():
    inertia, height, gradient = 8.3e-10, 0.01, 40.0
    model = (deploydyn.ModelBuilder("clamped beam")
             .node("A", 0, 0).node("B", 0.5, 0).node("C", 1, 0)
             .material("steel", E=E, alpha=ALPHA, density=7850)
             .beam("b1", "A", "B", area=AREA, inertia_z=inertia, material="steel",
                   height_y=height, dT_gradient_y=gradient)
             .beam("b2", "B", "C", area=AREA, inertia_z=inertia, material="steel",
                   height_y=height, dT_gradient_y=gradient)
             .support("A", fix=["x", "y", "rotation"]).support("C", fix=["x", "y", "rotation"])
             .analysis(type="static", end=1.0, step=1.0)
             .build())
    assert model.elements["b1"]["type"] == "beam"
    assert model.supports[0]["fix"] == ["x", "y", "rotation"]
    assert "rz.B" in model.history_columns
    result = model.run(check=True)
    # Held straight, the beam carries M = −EIκ_t = EIαΔT_g/h and turns nowhere.
    assert result["moment.b1"][-1] == pytest.approx(E * inertia * ALPHA * gradient / height, rel=1e-9)
    assert abs(result["rz.B"][-1]) < 1e-12


def test_end_moment_on_a_beam_node_is_read_and_a_bar_node_rejects_it():
    builder = (deploydyn.ModelBuilder("cantilever")
               .node("A", 0, 0).node("B", 1, 0).node("C", 2, 0)
               .material("steel", E=E, density=7850)
               .beam("b", "A", "B", area=AREA, inertia_z=8.3e-10, material="steel")
               .bar("r", "B", "C", area=AREA, material="steel")
               .support("A", fix=["x", "y", "rotation"]).support("C")
               .load("B", moment=1.5))
    assert builder.build().to_yaml().count("moment: 1.5") == 1
    with pytest.raises(ValueError, match="has no rotation for a moment to act on"):
        builder.load("C", moment=2.0).build()


def test_a_moment_vector_bends_a_3d_cantilever_into_its_arc():
    # End moment about z, M L/EI = 1 rad: the tip on the arc (L sin φ/φ, L (1 − cos φ)/φ)
    # (docs/theory.md, "Moments on 3D beam nodes"); 16 elements, whose curvature is second
    # order in their turn, are within 2e-3 L of it.
    inertia, n = 1e-10, 16
    builder = deploydyn.ModelBuilder("curled").material("steel", E=E, density=7850)
    for i in range(n + 1):
        builder.node(f"N{i}", i / n, 0, 0)
    for i in range(n):
        builder.beam(f"b{i}", f"N{i}", f"N{i + 1}", area=AREA, inertia_z=inertia, inertia_y=4 * inertia,
                     torsion=5 * inertia, orientation=[0, 1, 0], material="steel")
    phi = 1.0
    model = (builder.support("N0", fix=["x", "y", "z", "rotation"])
             .load(f"N{n}", moment=[0, 0, phi * E * inertia], factor=deploydyn.smooth_step(0, 0, 1, 1))
             .analysis(type="static", end=1.0, step=0.25).build())
    assert model.to_yaml().count("moment:") == 1
    result = model.run()
    assert result[f"x.N{n}"][-1] == pytest.approx(math.sin(phi) / phi, abs=2e-3)
    assert result[f"y.N{n}"][-1] == pytest.approx((1 - math.cos(phi)) / phi, abs=2e-3)
    with pytest.raises(TypeError, match="moment"):
        deploydyn.ModelBuilder("x").load("A", moment="1")


def test_pin_joint_and_hinge_angle_driver_move_a_two_bar_chain():
    # Crank H–B turned by 0.3 rad about H by a hinge_angle driver measured from H→A; bar C–D is
    # pinned to the crank's tip (C at B) and slides with D along y = 1.
    turn = 0.3
    model = (deploydyn.ModelBuilder("knee")
             .node("A", 0, 0).node("H", 1, 0).node("B", 1, 1).node("C", 1, 1).node("D", 2, 1)
             .material("steel", E=E, alpha=ALPHA, density=7850)
             .bar("crank", "H", "B", area=AREA, material="steel")
             .bar("link", "C", "D", area=AREA, material="steel")
             .support("A").support("H").support("D", fix=["y"])
             .joint("knee", "B", "C")
             .hinge_angle_driver("arm", "A", "H", "B", deploydyn.smooth_step(0, 0, 1, turn),
                                 reading="angle")
             .analysis(type="static", end=1.0, step=0.1)
             .build())
    assert model.joints == {"knee": {"name": "knee", "type": "pin", "nodes": ["B", "C"]}}
    assert model.drivers["arm"]["nodes"] == ["A", "H", "B"]
    assert model.drivers["arm"]["effort"] == "torque"
    assert "joints:" in model.to_yaml()
    result = model.run(check=True)
    assert result["x.B"][-1] == pytest.approx(1 - math.sin(turn), abs=1e-9)
    assert result["y.B"][-1] == pytest.approx(math.cos(turn), abs=1e-9)
    assert result["x.C"][-1] == pytest.approx(result["x.B"][-1], abs=1e-12)
    assert result["y.C"][-1] == pytest.approx(result["y.B"][-1], abs=1e-12)
    rise = 1 - math.cos(turn)
    assert result["x.D"][-1] == pytest.approx(result["x.C"][-1] + math.sqrt(1 - rise**2), abs=1e-9)
    assert "torque.arm" in result.columns


def test_a_pretensioned_cable_between_pins_goes_slack_when_heated():
    """docs/theory.md "Cables" (C7): slack above ΔT* = ε*/α, ε*²(1 + 2ε*) = (T0/EA)²."""
    tension, area = 2000.0, 1.0e-5
    tau = tension / (E * area)
    strain = tau
    for _ in range(50):  # Newton on ε²(1 + 2ε) − τ², from above the root
        strain -= (strain * strain * (1 + 2 * strain) - tau * tau) / (2 * strain + 6 * strain * strain)
    slack_dT = strain / ALPHA
    model = (deploydyn.ModelBuilder("heated cable")
             .node("A", 0, 0).node("B", 1.5, 0)
             .material("steel", E=E, alpha=ALPHA, density=7850)
             .cable("c", "A", "B", area=area, material="steel", pretension=tension)
             .support("A").support("B")
             .thermal(deploydyn.table([(0, 0), (1, 2 * slack_dT)]))
             .analysis(type="static", end=1.0, step=0.2)
             .build())
    result = model.run(check=True)
    assert result["force.c"][0] == pytest.approx(tension, rel=1e-12)
    # ε_m = ε − αΔT with the length held: zero at ΔT*. At t = 0.2, ΔT = 0.4 ΔT*.
    assert result["mstrain.c"][1] / ALPHA + 0.4 * slack_dT == pytest.approx(slack_dT, rel=1e-9)
    assert list(result["slack.c"]) == [0, 0, 0, 1, 1, 1]
    assert all(result["force.c"][:3] > 0) and list(result["force.c"][3:]) == [0, 0, 0]


def test_spring_driven_hinge_latches_and_the_run_ends_there():
    # An arm H–B with a 1 kg tip turned by a preloaded torsion spring at H until its latch;
    # θ is the angle at H from H→A = (−1, 0) to H→B = (1, 0.2).
    theta0 = math.atan2(0.2, 1.0) - math.pi
    latch, rest = theta0 + 0.5, theta0 + 0.8
    model = (deploydyn.ModelBuilder("spring-driven arm")
             .node("A", -1, 0).node("H", 0, 0).node("B", 1, 0.2, mass=1.0)
             .material("steel", E=E, alpha=ALPHA)
             .bar("ground", "A", "H", area=AREA, material="steel", mass=1.0)
             .bar("arm", "H", "B", area=AREA, material="steel", mass=1e-6)
             .hinge("spring", nodes=["A", "H", "B"], stiffness=10.0, rest_angle=rest, latch=latch)
             .support("A").support("H")
             .analysis(type="dynamic", end=3.0, step=1e-3, end_when="all_latched",
                       integrator={"type": "generalized_alpha", "rho_inf": 0.9})
             .build())
    assert model.elements["spring"]["type"] == "hinge"
    result = model.run(check=True)
    assert result["hinge_angle.spring"][-1] == pytest.approx(latch, abs=1e-12)
    # Released from rest, θ = θ_r − 0.8 cos(ω t) reaches the latch at cos(ω t) = 3/8.
    omega = math.sqrt(10.0 / (1.0 + 0.2 ** 2))
    assert result["t"][-1] == pytest.approx(math.acos(0.3 / 0.8) / omega, abs=2e-3)


def test_material_damping_and_strength_reach_the_model_and_the_verdict():
    """ModelBuilder.material's damping and yield_strength are the model file's keys: the
    damping time τ = ζ / (π f) is what the run's model writes back, and the strength makes the
    stress check run, at |σ| = EαΔT of the heated bar held by its pins."""
    dT, strength = 100.0, 400e6
    model = (deploydyn.ModelBuilder("damped heated bar")
             .node("A", 0, 0).node("B", 1.5, 0)
             .material("steel", E=E, alpha=ALPHA, damping={"ratio": 0.02, "frequency": 10},
                       yield_strength=strength)
             .bar("1", "A", "B", area=AREA, material="steel", mass=1.2)
             .support("A").support("B")
             .thermal(deploydyn.smooth_step(0, 0, 1, dT))
             .analysis(type="static", end=1.0, step=0.25)
             .build())
    assert "time: " + repr(0.02 / (math.pi * 10))[:8] in model.to_yaml()
    verdict = model.run(check=True).summary["verdict"]
    assert verdict["deploys"] is True
    assert verdict["checks"]["stress"]["max_utilization"] == pytest.approx(E * ALPHA * dT / strength, rel=1e-9)
    with pytest.raises(TypeError, match="damping must be a dict"):
        deploydyn.ModelBuilder("x").material("steel", E=E, damping=0.02)


def test_material_tables_of_temperature_reach_the_model():
    """E and alpha as data-sheet tables (docs/theory.md, "Temperature-dependent material
    properties"): the pinned bar at T = 20 + 230 °C carries N = −E(T) A ε_t(T), ε_t = ∫α dT."""
    dT = 230.0
    model = (deploydyn.ModelBuilder("heated bar, tables")
             .node("A", 0, 0).node("B", 1.5, 0)
             .material("steel", E={"temperature_C": [20, 400], "value": [2.1e11, 1.7e11]},
                       alpha={"temperature_C": [20, 200, 400], "value": [1.2e-5, 1.3e-5, 1.4e-5]})
             .bar("1", "A", "B", area=AREA, material="steel", mass=1.2)
             .support("A").support("B")
             .thermal(dT, reference_temperature_C=20)
             .analysis(type="static", end=1.0, step=0.5)
             .build())
    youngs = 2.1e11 - 0.4e11 * dT / 380.0
    # ∫ from 20 to 200 °C, then from 200 to 250 °C (α(250) = 1.325e-5): trapezoids of linear α.
    strain = 180.0 * 1.25e-5 + 50.0 * (1.3e-5 + 1.325e-5) / 2
    assert model.run(check=True)["force.1"][-1] == pytest.approx(-youngs * AREA * strain, rel=1e-12)
    assert "temperature_C: [20, 200, 400]" in model.to_yaml()
    with pytest.raises(TypeError, match="needs exactly the keys 'temperature_C' and 'value'"):
        deploydyn.ModelBuilder("x").material("steel", E={"T": [20], "value": [2e11]})


def test_ball_and_universal_joints_and_a_hinge_to_ground_reach_the_model():
    # The Cardan shaft of examples/joints/cardan_shaft.yaml, built in code: the output (30° from
    # the input) turns unevenly, tan ψ = tan φ / cos β (docs/theory.md, Eq. J3).
    beta = math.pi / 6
    c, s = math.cos(beta), math.sin(beta)
    shaft = dict(material="steel", area=7.07e-4, inertia_y=3.98e-8, inertia_z=3.98e-8, torsion=7.95e-8)
    model = (deploydyn.ModelBuilder("cardan")
             .node("G0", -1.2, 0, 0).node("G1", -1, 0, 0).node("S0", -1, 0, 0).node("S1", 0, 0, 0)
             .node("T0", 0, 0, 0).node("T1", c, s, 0).node("P", 0, 0, 0)
             .material("steel", E=E, density=7850)
             .beam("stub", "G0", "G1", **shaft).beam("input", "S0", "S1", **shaft)
             .beam("output", "T0", "T1", **shaft).bar("lug", "P", "T1", area=AREA, material="steel")
             .support("G1", fix=["x", "y", "z", "rotation"])
             .support("T1", axis=[c, s, 0], offset=[0, 0, 0])
             .joint("motor_hinge", "G1", "S0", axis=[1, 0, 0])
             .universal_joint("cross", "S1", "T0", arms=[[0, 1, 0], [0, 0, 1]])
             .ball_joint("lug_end", "T0", "P")
             .revolute_driver("motor", "motor_hinge", deploydyn.smooth_step(0, 0, 1, 1.0), reading="angle")
             .analysis(type="static", end=1.0, step=0.25)
             .build())
    assert model.joints["cross"]["type"] == "universal"
    assert [list(arm) for arm in model.joints["cross"]["arms"]] == [[0, 1, 0], [0, 0, 1]]
    assert model.joints["lug_end"]["type"] == "ball"
    assert model.supports[1]["axis"] == pytest.approx([c, s, 0])
    assert "universal" in model.to_yaml()
    result = model.run(check=True)
    # The output turns about its axis: T0's third director column turned from z by ψ.
    phi = 1.0
    psi = math.atan2(math.sin(phi), c * math.cos(phi))
    z_turned = np.array([result[f"R{i}3.T0"][-1] for i in (1, 2, 3)])
    assert z_turned @ np.array([0, 0, 1]) == pytest.approx(math.cos(psi), abs=1e-6)


@pytest.mark.parametrize("dimension", [2, 3])
def test_a_revolute_driver_at_a_hinge_to_ground_holds_the_weight(dimension):
    """revolute_driver(support=...) turns a beam about its hinge to ground (no stub beam): in
    statics its torque holds the weight, m g (L/2) cos θ (docs/theory.md, "Revolute driver at a
    hinge to ground")."""
    density, area, length, g = 2700.0, 2.0e-3, 1.0, 9.81
    b = deploydyn.ModelBuilder("crank").material("stiff", E=2.0e12, density=density)
    z = [0] if dimension == 3 else []
    b.node("A", 0, 0, *z).node("M", length / 2, 0, *z).node("B", length, 0, *z)
    section = dict(area=area, inertia_z=3e-7, material="stiff")
    if dimension == 3:
        section.update(inertia_y=3e-7, torsion=6e-7)
    b.beam("b0", "A", "M", **section).beam("b1", "M", "B", **section)
    if dimension == 3:
        b.support("A", axis=[0, 0, 1])
    else:
        b.support("A", fix=["x", "y"])
    b.gravity([0, -g] + z)
    b.revolute_driver("crank", support="A", profile=deploydyn.smooth_step(0, 0, 1, 1.0), reading="angle")
    b.analysis(type="static", end=1.0, step=0.25)
    model = b.build()
    assert model.drivers["crank"]["support"] == "A"
    assert "support: A" in model.to_yaml()
    result = model.run(check=True)
    # The tip lags the driven 1 rad by the beam's sag under its weight (~6e-6 rad here).
    theta = math.atan2(result["y.B"][-1], result["x.B"][-1])
    assert theta == pytest.approx(1.0, abs=1e-4)
    weight_moment = density * area * length * g * length / 2
    assert result["torque.crank"][-1] == pytest.approx(weight_moment * math.cos(theta), rel=5e-6)
    with pytest.raises(TypeError, match="give either joint .* or support"):
        deploydyn.ModelBuilder("x").revolute_driver("m", "hinge", 0.1, support="A")


def test_joint_arms_must_be_two_vectors():
    builder = deploydyn.ModelBuilder("bad")
    with pytest.raises(TypeError, match="arms must be two vectors"):
        builder.joint("j", "A", "B", type="universal", arms=[0, 1, 0])


@pytest.mark.parametrize("dimension", [2, 3])
def test_a_beam_given_by_its_sectional_values_bends_as_timoshenko(dimension):
    """The builder takes a beam's sectional values (docs/model-format.md, "Sectional values"):
    in 3D vectors per local axis, in 2D the in-plane numbers. A cantilever of the thin strip's
    GA_y = 5.0e6 N, GA_z = 23.4e6 N under tip loads along y and z deflects by
    PL³/(3EI) + PL/GA in each plane; its material and geometry alone (EI = 2e3 N·m²) would
    bend it some 300× further."""
    n, ei_y, ei_z, ga_y, ga_z = 16, 2.0e6, 1.0e6, 5.0e6, 23.4e6
    b = deploydyn.ModelBuilder("Timoshenko cantilever").material("steel", E=E, density=7850)
    for i in range(n + 1):
        b.node(f"N{i}", i / n, 0, *([0] if dimension == 3 else []))
    per_axis = (lambda v3, v2: v3) if dimension == 3 else (lambda v3, v2: v2)
    for i in range(n):
        extra = {"inertia_y": 1e-8, "torsion": 2e-8, "orientation": [0, 1, 0],
                 "torsional_stiffness": 1e6} if dimension == 3 else {}
        b.beam(f"b{i}", f"N{i}", f"N{i + 1}", area=AREA, inertia_z=1e-8, material="steel",
               mass_per_length=1.0, rotary_inertia_per_length=per_axis([2.0, 1.0, 1.0], 1.0),
               axial_stiffness=1e9, bending_stiffness=per_axis([ei_y, ei_z], ei_z),
               shear_stiffness=per_axis([ga_y, ga_z], ga_y), **extra)
    b.support("N0", fix=["x", "y", "z", "rotation"] if dimension == 3 else ["x", "y", "rotation"])
    b.load(f"N{n}", force=[0, 1.0, 1.0] if dimension == 3 else [0, 1.0])
    b.analysis(type="static", end=1.0, step=1.0)
    result = b.build().run(check=True)
    # The bending part converges as O(L0²): PL³/(12 EI n²) too much at n elements.
    assert result[f"y.N{n}"][-1] == pytest.approx(1 / (3 * ei_z) + 1 / ga_y, rel=2e-3)
    if dimension == 3:
        assert result[f"z.N{n}"][-1] == pytest.approx(1 / (3 * ei_y) + 1 / ga_z, rel=2e-3)


def test_a_2d_beam_off_its_centroid_bends_under_an_axial_force():
    """Issue 33 in the builder: a 2D cantilever whose elastic centroid is e off its line, given as
    centroid_offset (a number in 2D) or as the 3 × 3 sectional_stiffness Tᵀ diag T, bends under an
    axial tip force P on the line by P e L²/(2EI) (docs/theory.md, "Sections with offsets")."""
    n, ea, ga, ei, e, load = 8, 1.0e7, 5.0e6, 1.0e3, 0.01, 0.1

    def tip(**section):
        b = deploydyn.ModelBuilder("offset cantilever").material("steel", E=E, density=7850)
        for i in range(n + 1):
            b.node(f"N{i}", i / n, 0)
        for i in range(n):
            b.beam(f"b{i}", f"N{i}", f"N{i + 1}", area=AREA, inertia_z=1e-8, material="steel",
                   mass_per_length=1.0, **section)
        b.support("N0", fix=["x", "y", "rotation"])
        b.load(f"N{n}", force=[load, 0])
        b.analysis(type="static", end=1.0, step=1.0)
        return b.build().run(check=True)[f"y.N{n}"][-1]

    by_keys = tip(axial_stiffness=ea, shear_stiffness=ga, bending_stiffness=ei, centroid_offset=e)
    by_matrix = tip(sectional_stiffness=[ea, 0, -ea * e, 0, ga, 0, -ea * e, 0, ei + ea * e * e])
    assert by_keys == pytest.approx(load * e / (2 * ei), rel=1e-4)
    assert by_matrix == pytest.approx(by_keys, rel=1e-10)


def test_a_3d_beam_takes_its_sectional_mass_or_the_full_rotary_inertia_tensor():
    """Issue 33 in the builder: a 3D cantilever whose section is given by its 6 × 6 sectional_mass
    (μ, the mass centroid y_m off the line, J with a product J_yz) sags and twists under its weight
    as the one given by mass_per_length, the six-number rotary_inertia_per_length and
    mass_centroid_offset; the weight off the line twists it by −μ g y_m L²/(2GJ)."""
    n, mu, y_m, gj, g = 4, 2.0, 0.25, 8.0e2, 9.81
    j_c = [[12.0, 0.0, 0.0], [0.0, 9.0, -2.0], [0.0, -2.0, 5.0]]
    # About the axis: J_c + μ(|S|² I − S Sᵀ), S = (0, y_m, 0).
    j = [[j_c[0][0] + mu * y_m**2, 0.0, 0.0], [0.0, j_c[1][1], j_c[1][2]], [0.0, j_c[2][1], j_c[2][2] + mu * y_m**2]]
    sectional_mass = [mu, 0, 0, 0, 0, -mu * y_m,
                      0, mu, 0, 0, 0, 0,
                      0, 0, mu, mu * y_m, 0, 0,
                      0, 0, mu * y_m, *j[0],
                      0, 0, 0, *j[1],
                      -mu * y_m, 0, 0, *j[2]]

    def run(**section):
        b = deploydyn.ModelBuilder("sagging cantilever").material("steel", E=E, density=7850)
        for i in range(n + 1):
            b.node(f"N{i}", i / n, 0, 0)
        for i in range(n):
            b.beam(f"b{i}", f"N{i}", f"N{i + 1}", area=AREA, inertia_z=1e-8, material="steel",
                   inertia_y=1e-8, torsion=2e-8, orientation=[0, 1, 0], axial_stiffness=1e9,
                   shear_stiffness=[1e8, 1e8], torsional_stiffness=gj, bending_stiffness=[1e6, 1e6], **section)
        b.support("N0", fix=["x", "y", "z", "rotation"])
        b.gravity([0, 0, -g])
        b.analysis(type="static", end=1.0, step=1.0)
        result = b.build().run(check=True)
        return result[f"z.N{n}"][-1], result[f"R32.N{n}"][-1]  # R32 ≈ the twist about x

    keys = run(mass_per_length=mu, mass_centroid_offset=[y_m, 0],
               rotary_inertia_per_length=[j_c[0][0], j_c[1][1], j_c[2][2], 0, 0, j_c[1][2]])
    full = run(sectional_mass=sectional_mass)
    assert full == pytest.approx(keys, rel=1e-12)
    assert keys[1] == pytest.approx(-mu * g * y_m / (2 * gj), rel=1e-4)


def test_a_member_of_a_tube_section_is_checked_against_its_euler_load():
    """Issue 27 in the builder: a heated tube strut between pins, one member with a given K,
    carries N = E A α ΔT against N_cr = π² E I / (K L)² and its stress N/A against f_y."""
    d, t, dT, K, f_y = 0.02, 0.002, 50.0, 0.7, 3.55e8
    area = math.pi / 4 * (d**2 - (d - 2 * t)**2)
    inertia = math.pi / 64 * (d**4 - (d - 2 * t)**4)
    model = (deploydyn.ModelBuilder("heated strut")
             .node("A", 0, 0).node("B", 1, 0)
             .material("steel", E=E, alpha=ALPHA, density=7850, yield_strength=f_y)
             .cross_section("tube", "circular_tube", outer_diameter=d, wall_thickness=t)
             .element("s", "bar", nodes=["A", "B"], section="tube", material="steel")
             .member("strut", ["s"], buckling_length_factor=K)
             .support("A").support("B")
             .thermal(dT)
             .checks(clearance=False)
             .analysis(type="static", end=1.0, step=0.5)
             .build())
    verdict = model.run(check=True).summary["verdict"]
    strut = verdict["members"]["strut"]
    assert strut["buckling_length_factor"] == K and strut["buckling_length_source"] == "given"
    euler = math.pi**2 * E * inertia / K**2
    assert strut["buckling"]["utilization"] == pytest.approx(E * area * ALPHA * dT / euler, rel=1e-9)
    assert strut["stress"]["utilization"] == pytest.approx(E * ALPHA * dT / f_y, rel=1e-9)
    assert verdict["deploys"] and "clearance" not in verdict["checks_run"]


def test_a_3d_beam_member_takes_k_per_axis_and_a_cable_member_its_slack_rule():
    builder = (deploydyn.ModelBuilder("boom")
               .node("A", 0, 0, 0).node("B", 1, 0, 0).node("C", 2, 0, 0)
               .material("steel", E=E, density=7850)
               .element("b1", "beam", nodes=["A", "B"], area=AREA, inertia_y=1e-8, inertia_z=2e-8,
                        torsion=2e-8, material="steel")
               .element("b2", "beam", nodes=["B", "C"], area=AREA, inertia_y=1e-8, inertia_z=2e-8,
                        torsion=2e-8, material="steel")
               .member("boom", ["b1", "b2"], buckling_length_factor=[0.7, 2.1])
               .support("A", fix=["x", "y", "z", "rotation"]))
    assert "buckling_length_factor: [0.7, 2.1]" in builder.build().to_yaml()
    with pytest.raises(TypeError, match="ModelBuilder.member: elements"):
        builder.member("bad", "b1")
    builder.node("D", 2, 1, 0).element("c", "cable", nodes=["C", "D"], area=1e-5, material="steel")
    assert "guy: {elements: [c], slack: forbidden}" in builder.member("guy", ["c"], slack="forbidden").build().to_yaml()
    strut = (deploydyn.ModelBuilder("strut").node("A", 0, 0).node("B", 1, 0).material("steel", E=E)
             .bar("s", "A", "B", area=AREA, material="steel", mass=1.0).support("A").support("B"))
    with pytest.raises(deploydyn.InputError, match="members.stay.slack: applies to cables"):
        strut.member("stay", ["s"], slack="forbidden").build()
