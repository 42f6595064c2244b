#include "TupleExtremes.h"

namespace LaplacianEditing
{
namespace Pipeline
{
void TupleExtremes::Reset(int components)
{
  this->Components = std::min(components, MaximumComponents);
  this->Count = 0;
  this->Split = false;
  for (int f = 0; f < 2; ++f)
  {
    std::fill(this->Low[f], this->Low[f] + MaximumComponents + 1, std::numeric_limits<double>::infinity());
    std::fill(this->High[f], this->High[f] + MaximumComponents + 1, -std::numeric_limits<double>::infinity());
  }
}

void TupleExtremes::Merge(const TupleExtremes& other)
{
  if (other.Split && !this->Split)
  {
    std::copy(this->Low[0], this->Low[0] + MaximumComponents + 1, this->Low[1]);
    std::copy(this->High[0], this->High[0] + MaximumComponents + 1, this->High[1]);
    this->Split = true;
  }
  for (int f = 0; f < 2; ++f)
  {
    // The other's finite extremes are its plain ones where it never split.
    const int from = f == 1 && !other.Split ? 0 : f;
    if (f == 1 && !this->Split)
    {
      continue;
    }
    for (int c = 0; c <= MaximumComponents; ++c)
    {
      this->Low[f][c] = std::min(this->Low[f][c], other.Low[from][c]);
      this->High[f][c] = std::max(this->High[f][c], other.High[from][c]);
    }
  }
  this->Count += other.Count;
}

std::array<TupleExtremes::Family, TupleExtremes::Families> TupleExtremes::Get() const
{
  std::array<Family, Families> families;
  for (int f = 0; f < Families; ++f)
  {
    const int source = f % 2 == 1 && this->Split ? 1 : 0; // finite families: 1 and 3
    if (f < 2)
    {
      families[f].resize(2 * this->Components);
      for (int c = 0; c < this->Components; ++c)
      {
        families[f][2 * c] = this->Low[source][c];
        families[f][2 * c + 1] = this->High[source][c];
      }
    }
    else
    {
      const double high = this->High[source][MaximumComponents];
      families[f] = { std::sqrt(this->Low[source][MaximumComponents]),
        high >= 0.0 ? std::sqrt(high) : high };
    }
  }
  return families;
}
}
}
