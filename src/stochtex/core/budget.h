#pragma once
// Work and memory budgets. A small input can ask for minutes and gigabytes
// (a graph of 4096² noises, a shader whose macros expand exponentially, a
// list of 2000 tile sizes); the library estimates such a request before
// doing it and refuses what exceeds its budget with InputError::overBudget.
// Each budget is a base amount (stated where it is checked and in the
// README) times one process-wide factor, 1 unless the user raises or lowers
// it: a machine with more memory or patience may allow more.
namespace stochtex {

constexpr double kMinBudgetFactor = 1.0 / 64, kMaxBudgetFactor = 64;

// The factor every budget is multiplied by (1 unless set).
double budgetFactor();
// InputError naming `budget` unless factor is in [kMinBudgetFactor, kMaxBudgetFactor].
void setBudgetFactor(double factor);

// `base` × the factor, at least 1 (counts of texels, bytes, operations).
long long budgeted(long long base);
// `base` × the factor (a time in seconds).
double budgetedSeconds(double base);

}  // namespace stochtex
