@echo off
rem D-former for Adobe Illustrator: removes the panel installed by install-windows.cmd.
rem PlayerDebugMode is left as it is: other unsigned panels may need it
rem (to reset it: reg delete HKCU\Software\Adobe\CSXS.N /v PlayerDebugMode /f, N = 8 to 12).
setlocal
set "DEST=%APPDATA%\Adobe\CEP\extensions\com.dformer.panel"
if exist "%DEST%" (
  rmdir /s /q "%DEST%"
  echo D-former is removed from %DEST%. Restart Illustrator.
) else (
  echo D-former is not installed for this user ^(no folder %DEST%^).
)
if not defined DFORMER_NO_PAUSE pause
exit /b 0
