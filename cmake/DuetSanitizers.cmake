# AddressSanitizer + UndefinedBehaviorSanitizer for every host target; any report fails the test that caused it.
if(DUET_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
