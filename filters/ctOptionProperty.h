/**
 * Properties of a filter stored in the core options struct of its stage, so that every
 * parameter has one default: the struct's. The header declares each property's Set/Get pair
 * (the wrappers read plain declarations); the source defines it with one of these macros,
 * followed by a semicolon.
 */
#ifndef ctOptionProperty_h
#define ctOptionProperty_h

#include <algorithm>

/// Stores `value` into `member` and marks `algorithm` modified when it changes.
template <class Algorithm, class T> void ctSetOption(Algorithm* algorithm, T& member, T value)
{
  if (member == value) return;
  member = value;
  algorithm->Modified();
}

/// Set<Name> clamps to [low, high] and stores into this-><member>; Get<Name> reads it back.
#define ctOptionClampDefinition(cls, name, type, member, low, high)                                \
  void cls::Set##name(type value)                                                                  \
  {                                                                                                \
    ctSetOption(this, this->member, std::clamp<type>(value, low, high));                           \
  }                                                                                                \
  type cls::Get##name()                                                                            \
  {                                                                                                \
    return this->member;                                                                           \
  }                                                                                                \
  static_assert(true, "a semicolon follows")

/// The same without a range (booleans).
#define ctOptionDefinition(cls, name, type, member)                                                \
  void cls::Set##name(type value)                                                                  \
  {                                                                                                \
    ctSetOption(this, this->member, value);                                                        \
  }                                                                                                \
  type cls::Get##name()                                                                            \
  {                                                                                                \
    return this->member;                                                                           \
  }                                                                                                \
  static_assert(true, "a semicolon follows")

/// An enumeration stored as the core's enum class, set and read as its int value in [low, high].
#define ctOptionEnumDefinition(cls, name, enumType, member, low, high)                             \
  void cls::Set##name(int value)                                                                   \
  {                                                                                                \
    ctSetOption(this, this->member, static_cast<enumType>(std::clamp<int>(value, low, high)));     \
  }                                                                                                \
  int cls::Get##name()                                                                             \
  {                                                                                                \
    return static_cast<int>(this->member);                                                         \
  }                                                                                                \
  static_assert(true, "a semicolon follows")

#endif
