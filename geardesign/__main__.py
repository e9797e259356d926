from geardesign.cli import main

main()
