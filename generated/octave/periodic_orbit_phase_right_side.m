function r = periodic_orbit_phase_right_side(M, K, C, m, e, d, F0, X_b, Omega)
% PERIODIC_ORBIT_PHASE_RIGHT_SIDE  Right side c of a·cos φ + b·sin φ = c [kg m/s], Eq. F3 (derived here, beyond the paper).
%
%   r = periodic_orbit_phase_right_side(M, K, C, m, e, d, F0, X_b, Omega)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped) [N s/m]
%   m: Impact mass m [kg]
%   e: Coefficient of restitution e [1]
%   d: Total clearance d [m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% c = - \frac{d e \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{\Omega^{2}} - \frac{d e \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{\Omega^{2}} - \frac{d e \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right)}{\Omega^{2}} - \frac{d e}{\Omega^{2}} + \frac{d e \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\Omega^{2} \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \frac{d \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{\Omega^{2}} + \frac{d \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{\Omega^{2}} + \frac{d \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right)}{\Omega^{2}} + \frac{d}{\Omega^{2}} - \frac{d \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\Omega^{2} \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} - \frac{2 d e m \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{M \Omega^{2}} - \frac{2 d e m \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right)}{M \Omega^{2}} + \frac{2 d e m \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{M \Omega^{2} \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \frac{2 d m \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{M \Omega^{2}} + \frac{2 d m}{M \Omega^{2}}
%
% Generated by derive/periodic_orbit.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.periodic_orbit.phase_right_side; operations: 65.
  x_0 = d./Omega.^2;
  x_1 = e.*x_0;
  x_2 = 1./M;
  x_3 = 2*m.*x_2;
  x_4 = pi./Omega;
  x_5 = C.*x_2/2;
  x_6 = exp(-x_4.*x_5);
  x_7 = sqrt(-C.^2./(4*M.^2) + K.*x_2);
  x_8 = x_4.*x_7;
  x_9 = cos(x_8);
  x_10 = sin(x_8);
  x_11 = x_10./x_7;
  x_12 = x_11.*x_5;
  x_13 = x_6.*(x_12 + x_9);
  x_14 = x_0.*x_13;
  x_15 = x_0.*(-x_12.*x_6 + x_6.*x_9);
  x_16 = e.*x_15;
  x_17 = x_13.*x_16;
  x_18 = x_11.*x_6.*(-x_13.*x_5 + x_6.*(-x_10.*x_7 + x_5.*x_9));
  x_19 = x_1.*x_18;
  r = -x_0.*x_18 + x_0.*x_3 + x_0 - x_1.*x_13 - x_1 + x_13.*x_15 + x_14.*x_3 + x_14 + x_15 - x_16.*x_3 - x_16 - x_17.*x_3 - x_17 + x_19.*x_3 + x_19;
  r = r + zeros(size(M + K + C + m + e + d + F0 + X_b + Omega));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
