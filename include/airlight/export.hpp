#pragma once
// What libairlight exports. Every layer compiles with -fvisibility=hidden, so
// the library's dynamic symbol table holds only what carries AIRLIGHT_API: the
// declarations of include/airlight/. The public types carry it too, so that a
// program sees the library's type information for them — it catches InputError
// and Failure by type, and a Method's typeinfo and vtable are the library's.
#define AIRLIGHT_API __attribute__((visibility("default")))
