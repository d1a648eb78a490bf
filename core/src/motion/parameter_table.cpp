#include "parameter_table.hpp"

#include <iterator>
#include <stdexcept>
#include <string>

#include "motion_parameters.hpp"

namespace popup::motion {

namespace {

using R = ParameterRole;

/// A parameter the search steps: its name and role, and where it lives in its kind's params.
template <class Motion> struct Field {
    ParameterInfo info;
    double& (*of)(Motion&);
};

using V = VerticalMotion;
using D = DiagonalMotion;
using H = HorizontalMotion;
using Ro = RotationMotion;
using S = StationaryMotion;

const Field<V> vertical_fields[] = {
    {{"offset", R::position}, [](V& x) -> double& { return x.offset; }},
    {{"side", R::length}, [](V& x) -> double& { return x.side; }},
    {{"height", R::length}, [](V& x) -> double& { return x.height; }},
    {{"wall_angle", R::angle}, [](V& x) -> double& { return x.wall_angle; }},
};

const Field<D> diagonal_fields[] = {
    {{"offset", R::position}, [](D& x) -> double& { return x.v_fold.offset; }},
    {{"run", R::length}, [](D& x) -> double& { return x.v_fold.run; }},
    {{"hinge_angle", R::angle}, [](D& x) -> double& { return x.v_fold.hinge_angle; }},
    {{"spine", R::length}, [](D& x) -> double& { return x.v_fold.spine; }},
    {{"step_offset", R::length}, [](D& x) -> double& { return x.step.offset; }},
    {{"step_width", R::length}, [](D& x) -> double& { return x.step.width; }},
    {{"run_ground", R::length}, [](D& x) -> double& { return x.step.run_ground; }},
    {{"run_backdrop", R::length}, [](D& x) -> double& { return x.step.run_backdrop; }},
};

const Field<H> horizontal_fields[] = {
    {{"offset", R::position}, [](H& x) -> double& { return x.offset; }},
    {{"width", R::length}, [](H& x) -> double& { return x.width; }},
    {{"run_ground", R::length}, [](H& x) -> double& { return x.run_ground; }},
    {{"run_backdrop", R::length}, [](H& x) -> double& { return x.run_backdrop; }},
    {{"reach", R::length}, [](H& x) -> double& { return x.reach; }},
};

const Field<Ro> rotation_fields[] = {
    {{"offset", R::position}, [](Ro& x) -> double& { return x.offset; }},
    {{"spine", R::length}, [](Ro& x) -> double& { return x.spine; }},
    {{"run", R::length}, [](Ro& x) -> double& { return x.run; }},
    {{"arm", R::length}, [](Ro& x) -> double& { return x.arm; }},
    {{"hinge", R::position}, [](Ro& x) -> double& { return x.hinge; }},
};

const Field<S> stationary_fields[] = {
    {{"offset", R::position}, [](S& x) -> double& { return x.offset; }},
    {{"width", R::length}, [](S& x) -> double& { return x.width; }},
    {{"height", R::length}, [](S& x) -> double& { return x.height; }},
    {{"support", R::length}, [](S& x) -> double& { return x.support; }},
    {{"overhang", R::length}, [](S& x) -> double& { return x.overhang; }},
    {{"anchor", R::position}, [](S& x) -> double& { return x.anchor; }},
};

const auto& fields_of(const V&)
{
    return vertical_fields;
}
const auto& fields_of(const D&)
{
    return diagonal_fields;
}
const auto& fields_of(const H&)
{
    return horizontal_fields;
}
const auto& fields_of(const Ro&)
{
    return rotation_fields;
}
const auto& fields_of(const S&)
{
    return stationary_fields;
}

/// f(the kind's table).
template <class F> auto with_fields(MotionKind kind, F f)
{
    switch (kind) {
    case MotionKind::vertical:
        return f(vertical_fields);
    case MotionKind::diagonal:
        return f(diagonal_fields);
    case MotionKind::horizontal:
        return f(horizontal_fields);
    case MotionKind::rotation:
        return f(rotation_fields);
    case MotionKind::stationary:
        break;
    }
    return f(stationary_fields);
}

/// The row `index` of a kind's table, or an error naming the kind and the allowed range.
template <class Row, std::size_t N> const Row& row(const Row (&rows)[N], MotionKind kind, int index)
{
    if (index < 0 || index >= int(N))
        throw std::out_of_range(std::string("motion mechanism: parameter ") +
                                std::to_string(index) + " of a " + to_string(kind) +
                                ", must be in [0, " + std::to_string(N - 1) + "]");
    return rows[index];
}

} // namespace

int parameter_count(MotionKind kind)
{
    return with_fields(kind, [](const auto& fields) { return int(std::size(fields)); });
}

ParameterInfo parameter_info(MotionKind kind, int index)
{
    return with_fields(kind, [&](const auto& fields) { return row(fields, kind, index).info; });
}

int active_parameter_count(const MotionMechanism& m)
{
    if (m.kind() == MotionKind::rotation && !rotation_off_fold(m))
        return parameter_count(m.kind()) - 1; // all but the hinge, the table's last
    return parameter_count(m.kind());
}

double& parameter(MotionMechanism& m, int index)
{
    return std::visit(
        [&](auto& motion) -> double& { return row(fields_of(motion), m.kind(), index).of(motion); },
        m.params);
}

double parameter(const MotionMechanism& m, int index)
{
    // Reads only: the table's accessors are written once, for the mutable params.
    return parameter(const_cast<MotionMechanism&>(m), index);
}

} // namespace popup::motion
