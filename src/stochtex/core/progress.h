#pragma once
// How a long computation says how far it is: a callback taking the fraction
// of the work done, in [0, 1], and the step now running ("" keeps the step
// last named). Work is counted in steps, not seconds, so a fraction is an
// estimate of the time done. An empty callback reports nothing; the library
// never prints (the CLI draws the line).
#include <functional>
#include <string>

namespace stochtex {

using Progress = std::function<void(double fraction, const std::string& step)>;

// The part [from, to] of parent's range: f reported to the part is
// from + f·(to − from) to the parent, and a step named inside the part
// reads "name: step" (name alone where the part names none). Empty if
// parent is.
Progress progressPart(const Progress& parent, double from, double to, const std::string& name = "");

// Part `index` of `count` equal parts (progressPart of [index/count, (index+1)/count]).
Progress progressPart(const Progress& parent, int index, int count, const std::string& name = "");

}  // namespace stochtex
