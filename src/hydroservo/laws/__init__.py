"""Published laws: pure functions, one per law, NumPy and CasADi alike, each cited to its equation.

A law takes numbers (or arrays, or CasADi expressions) in SI units and returns
numbers; it knows nothing of components, systems or files. Components call
the laws in their equations; test benches and identification call the same
laws on arrays. A new law goes into the module of its physical kind:

======================  =======================================================
module                  laws
======================  =======================================================
:mod:`.fluid`           bulk modulus (Lee & Lee, Eggerth), density, wave speed,
                        line length; fluid properties against pressure and
                        temperature (Maré & Attar eqs. 1-2, Walther)
:mod:`.orifice`         the turbulent orifice law and its one regularisation at
                        null; flow number, transition pressure; catalogue flow
                        coefficient; the opened area and width of a round port
:mod:`.four_way`        the four-way bridge assembly; the sharp-edged spool
                        valve with per-edge laps (Efe)
:mod:`.pseudo_section`  pseudo-section valve (Ferreira et al.)
:mod:`.staged_slot`     staged-slot valve: unified open/closed orifice,
                        laminar to turbulent (Maré & Attar)
:mod:`.leakage`         earlier closed-orifice leakage laws (Ellman, Eryilmaz,
                        laminar gap)
:mod:`.spool_dynamics`  first- and second-order spools, rate limits, delay
:mod:`.torque_motor`    torque motor of a two-stage servovalve: second-order
                        armature; electromagnetic torque from the geometry
:mod:`.armature`        flexure tube, flapper bending, feedback spring with
                        clearance, impact on the nozzle
:mod:`.flapper_nozzle`  flapper-nozzle stage driving the main spool; its
                        conductances, nozzle pressures and null gap
:mod:`.servo_spool`     a servovalve's spool stage: real openings, port
                        flows, flow forces, leakage through the lapped lands
:mod:`.chamber`         pressure build-up in volumes and cylinder chambers
:mod:`.line`            lines as lumped segments: capacitance, inertance,
                        laminar resistance; segments for a frequency range
:mod:`.accumulator`     the polytropic gas spring of an accumulator
:mod:`.displacement`    pumps and motors: displaced flow, leakage, torque,
                        pressure compensator
:mod:`.centrifugal`     centrifugal pumps: Euler's impeller pressure, the flow
                        through the losses, the shaft's torque
:mod:`.axial_piston`    an axial piston machine's parts: the swash plate's
                        piston strokes, the valve plate's port openings
:mod:`.pressure_valve`  spring-loaded valves: opening against pressure,
                        the relief/reducing spool's flow coefficient
:mod:`.friction`        Stribeck friction
:mod:`.rigid_body`      Newton's second law on one axis: a mass, an inertia
======================  =======================================================
"""

from hydroservo.laws import (
    accumulator,
    armature,
    axial_piston,
    centrifugal,
    chamber,
    displacement,
    flapper_nozzle,
    fluid,
    four_way,
    friction,
    leakage,
    line,
    orifice,
    pressure_valve,
    pseudo_section,
    rigid_body,
    servo_spool,
    spool_dynamics,
    staged_slot,
    torque_motor,
)

__all__ = [
    "accumulator",
    "armature",
    "centrifugal",
    "axial_piston",
    "chamber",
    "displacement",
    "flapper_nozzle",
    "fluid",
    "four_way",
    "friction",
    "leakage",
    "line",
    "orifice",
    "pressure_valve",
    "pseudo_section",
    "rigid_body",
    "servo_spool",
    "spool_dynamics",
    "staged_slot",
    "torque_motor",
]
