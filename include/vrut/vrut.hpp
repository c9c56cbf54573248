#pragma once
// Everything device-safe in one include.
#include <vrut/contact/bond.hpp>
#include <vrut/contact/burgers.hpp>
#include <vrut/contact/choice.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/contact/concept.hpp>
#include <vrut/contact/geometry.hpp>
#include <vrut/contact/linear.hpp>
#include <vrut/core/assignment.hpp>
#include <vrut/core/contact_list.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/data/particles.hpp>
#include <vrut/core/simulation.hpp>
#include <vrut/data/vec2.hpp>
#include <vrut/data/walls.hpp>
#include <vrut/integrate/central_difference.hpp>
#include <vrut/servo/servo.hpp>
